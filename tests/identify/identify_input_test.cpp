// Bad input to `stride identify`: a truncated log, a log too short, a robot lying on the floor,
// parameters the simulated plant does not model or does not know, leg joints misnamed; each a
// one-line error naming what and where, and the command writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "console/cli/subcommand.hpp"
#include "console/identify/identify_log.hpp"
#include "console/identify/identify_params.hpp"
#include "robot/core/error.hpp"
#include "robot/runtime/log.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "tests/error_text.hpp"
#include "tests/identify/record_log.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using test_support::error_of;

sim::SceneDescription stand() {
  return sim::parse_scene_file(STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml");
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void expect_one_line(const std::string& what) {
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
}

TEST(IdentifyInput, TruncatedLogIsRefused) {
  const std::string bytes = read_all(test::record_log(stand(), 3, "id_whole.log"));
  const LogReader cut = LogReader::from_bytes(bytes.substr(0, bytes.size() - 100), "cut.log");
  const std::string what = error_of([&] { identify::read_identify_log(cut, "cut.log"); });
  EXPECT_NE(what.find("cut.log: truncated after frame"), std::string::npos) << what;
  expect_one_line(what);
}

TEST(IdentifyInput, ShortLogIsRefused) {
  const std::string path = test::record_log(stand(), 1, "id_short.log");
  const std::string what = error_of([&] { identify::read_identify_log(path); });
  EXPECT_NE(what.find("frames, expected at least 200"), std::string::npos) << what;
}

TEST(IdentifyInput, RobotLyingOnTheFloorIsRefused) {
  sim::SceneDescription s = stand();
  s.robots[0].rpy = {0, 1.5, 0};  // face down from the start
  const std::string path = test::record_log(s, 3, "id_lying.log");
  const std::string what = error_of([&] { identify::read_identify_log(path); });
  EXPECT_NE(what.find("a robot lying on the floor cannot be identified from"), std::string::npos)
      << what;
  expect_one_line(what);
}

TEST(IdentifyInput, MissingFileIsOneLine) {
  const std::string what = error_of([] { identify::read_identify_log("/nonexistent/x.log"); });
  EXPECT_NE(what.find("/nonexistent/x.log"), std::string::npos) << what;
  expect_one_line(what);
}

TEST(IdentifyInput, ParamsTheTestDoesNotModelAreNamed) {
  EXPECT_NE(error_of([] {
              identify::parse_param_list("gain,delay");
            }).find("'delay' cannot be identified: the simulated servo has no command delay"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              identify::parse_param_list("gain,wobble");
            }).find("unknown parameter 'wobble'; expected a comma-separated list of gain"),
            std::string::npos);
  EXPECT_NE(error_of([] { identify::parse_param_list("gain,gain"); }).find("given twice"),
            std::string::npos);
  EXPECT_NE(error_of([] { identify::parse_param_list(""); }).find("empty list"), std::string::npos);
  const auto c = identify::parse_param_list("gyro_bias,torque");
  EXPECT_TRUE(c.gyro_bias);
  EXPECT_EQ(c.kinds, std::vector{identify::ParamKind::torque});
}

TEST(IdentifyInput, JointsMustBeLegJoints) {
  EXPECT_EQ(identify::parse_joint_list("").size(), 10u);
  EXPECT_EQ(
      identify::parse_joint_list("RKneePitch,LHipRoll"),
      (std::vector{hal::index(hal::JointId::RKneePitch), hal::index(hal::JointId::LHipRoll)}));
  EXPECT_NE(error_of([] { identify::parse_joint_list("HeadYaw"); }).find("is not a leg joint"),
            std::string::npos);
  EXPECT_NE(error_of([] { identify::parse_joint_list("LHipYawPitch"); }).find("one motor"),
            std::string::npos);
}

// A robot override file that is not one: errors at its own line, or at the <include>.
TEST(IdentifyInput, BadRobotOverrideFileIsNamed) {
  const fs::path dir = fs::temp_directory_path();
  std::ofstream(dir / "not_override.xml") << "<scene/>";
  std::ofstream(dir / "bad_child.xml") << "<robot_override>\n  <joints LKneePitch=\"1\"/>\n"
                                          "</robot_override>";
  std::ofstream(dir / "bad_imu.xml") << "<robot_override>\n<imu gyro_bias=\"1 2\"/>\n"
                                        "</robot_override>";
  const auto scene_with = [&](const std::string& file) {
    return "<scene><robot urdf=\"" STRIDE_SOURCE_DIR
           "/scenes/robots/nao/nao.urdf\" devices=\"" STRIDE_SOURCE_DIR
           "/scenes/robots/nao/nao.devices.xml\">\n<include file=\"" +
           file + "\"/></robot></scene>";
  };
  const std::string at = (dir / "s.xml").string();
  const auto error = [&](const std::string& file) {
    return error_of([&] { sim::parse_scene_text(scene_with(file), at); });
  };
  EXPECT_NE(error("not_override.xml").find("not_override.xml:1: expected <robot_override>"),
            std::string::npos)
      << error("not_override.xml");
  EXPECT_NE(error("bad_child.xml")
                .find("bad_child.xml:2: <joints>: unexpected element in <robot_override>"),
            std::string::npos)
      << error("bad_child.xml");
  EXPECT_NE(error("bad_imu.xml").find("bad_imu.xml:2:"), std::string::npos) << error("bad_imu.xml");
  EXPECT_NE(error("missing.xml").find("s.xml:2:"), std::string::npos) << error("missing.xml");
}

// The command: a bad log writes no override file, a bad --params reads no log.
TEST(IdentifyInput, CommandWritesNothingOnError) {
  const auto& table = cli::subcommands();
  const auto it = std::ranges::find(table, std::string_view("identify"), &cli::Subcommand::name);
  ASSERT_NE(it, table.end());
  const std::string out = (fs::temp_directory_path() / "id_never.xml").string();
  fs::remove(out);
  const std::string lying = (fs::temp_directory_path() / "id_lying.log").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"/nonexistent/x.log", "--out", out},
        std::vector<std::string>{lying, "--out", out, "--params", "gain,friction"},
        std::vector<std::string>{lying, "--out", out, "--joints", "LElbowRoll"}}) {
    std::ostringstream o, e;
    EXPECT_NE(it->run(args, o, e), 0);
    expect_one_line(e.str().substr(0, e.str().size() - 1));
    EXPECT_FALSE(fs::exists(out));
  }
}

}  // namespace
}  // namespace stride
