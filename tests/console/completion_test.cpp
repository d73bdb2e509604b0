// Tab completion candidates for commands, keys, fields, providers and paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "console/repl/completion.hpp"
#include "console/target/local_target.hpp"

namespace stride::console {
namespace {

using Words = std::vector<std::string>;

class CompletionTest : public ::testing::Test {
 protected:
  LocalTarget target{STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml"};
};

TEST_F(CompletionTest, CommandNames) {
  EXPECT_EQ(complete({}, "re", target), (Words{"realtime", "report", "reset", "restart"}));
  EXPECT_EQ(complete({}, "ex", target), (Words{"expect"}));
  EXPECT_TRUE(complete({}, "zz", target).empty());
}

TEST_F(CompletionTest, KeysAndFields) {
  EXPECT_EQ(complete({"get"}, "mod", target), (Words{"module:"}));
  EXPECT_EQ(complete({"get"}, "module:St", target), (Words{"module:Stand"}));
  EXPECT_EQ(complete({"get"}, "representation:JointReq", target),
            (Words{"representation:JointRequest"}));
  EXPECT_EQ(complete({"watch"}, "module:Stand.kn", target), (Words{"module:Stand.knee_pitch"}));
  EXPECT_EQ(complete({"set", "module:Stand"}, "knee", target), (Words{"knee_pitch="}));
  EXPECT_EQ(complete({"expect"}, "robot.torso.p", target), (Words{"robot.torso.pitch"}));
  EXPECT_EQ(complete({"expect", "robot.fell"}, "!", target), (Words{"!="}));
}

TEST_F(CompletionTest, ProvidersSwitchesAndLogActions) {
  EXPECT_EQ(complete({"mr"}, "JointR", target), (Words{"JointRequest"}));
  const Words providers = complete({"mr", "JointRequest"}, "", target);
  for (const char* w : {"?", "Stand", "default"})
    EXPECT_NE(std::find(providers.begin(), providers.end(), w), providers.end()) << w;
  EXPECT_EQ(complete({"mr", "JointRequest"}, "St", target), (Words{"Stand"}));
  EXPECT_EQ(complete({"sn"}, "q", target), (Words{"quantise"}));
  EXPECT_EQ(complete({"sn", "noise"}, "o", target), (Words{"off", "on"}));
  EXPECT_EQ(complete({"log"}, "re", target), (Words{"replay"}));
}

TEST(CompletionTwoRobots, RobotNames) {
  LocalTarget two{STRIDE_SOURCE_DIR "/scenes/two_naos.xml"};
  EXPECT_EQ(complete({"robot"}, "b", two, two.robot_names()), (Words{"blue"}));
  EXPECT_EQ(complete({"robot"}, "", two, two.robot_names()), (Words{"?", "blue", "red"}));
  EXPECT_EQ(complete({"get"}, "robot.na", two), (Words{"robot.name"}));
}

TEST_F(CompletionTest, FilePaths) {
  const auto dir = std::filesystem::temp_directory_path() / "stride_completion_test";
  std::filesystem::create_directories(dir / "sub");
  std::ofstream(dir / "scene_a.xml") << "";
  const std::string base = dir.string() + "/";
  EXPECT_EQ(complete({"load"}, base + "sc", target), (Words{base + "scene_a.xml"}));
  EXPECT_EQ(complete({"call"}, base + "su", target), (Words{base + "sub/"}));
}

TEST(CompletionWithoutScene, OffersCommandsAndStaticKeysOnly) {
  LocalTarget empty;
  EXPECT_EQ(complete({"get"}, "representation:", empty), Words{});
  EXPECT_EQ(complete({"get"}, "sim.t", empty), (Words{"sim.time"}));
}

}  // namespace
}  // namespace stride::console
