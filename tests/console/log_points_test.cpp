// Issue 49 point 6: after `log goto`, robot.torso.roll/pitch are the logged frame's (its IMU) and
// what a log cannot show (a world pose, a picture) is refused in one line instead of showing the
// live simulation; `log export` takes the keys `get` takes; `log replay` without a scene says
// what it needs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"
#include "robot/core/error.hpp"

namespace stride::console {
namespace {

namespace fs = std::filesystem;
const std::string kScene = STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml";

std::string error_of(Interpreter& c, const std::string& line) {
  try {
    c.execute(line);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

class LogPointsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("stride_log_points_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    log = (dir / "tilt.log").string();
    console.execute("load " + kScene);
    console.execute("log start " + log);
    console.execute("run 0.3");
    console.execute("push torso 0 60 0 0.1");  // the torso rolls while the log records
    console.execute("run 0.5");
    console.execute("log stop");
    console.execute("log load " + log);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
  std::string log;
  LocalTarget target;
  std::ostringstream out;
  Interpreter console{target, out};
};

TEST_F(LogPointsTest, GotoShowsTheLoggedFrameInRobotTorsoKeys) {
  const std::string live = target.get("robot.torso.roll");
  console.execute("log goto 10");
  const std::string logged = target.get("representation:InertialSensorData.angles[0]");
  EXPECT_EQ(target.get("robot.torso.roll"), logged);
  EXPECT_NE(target.get("robot.torso.roll"), live);
  EXPECT_EQ(target.get("robot.torso.pitch"),
            target.get("representation:InertialSensorData.angles[1]"));
  const std::string x = error_of(console, "expect robot.torso.x > 0");
  EXPECT_NE(x.find("log frame 10 is shown and a log holds no world pose"), std::string::npos) << x;
  const std::string picture = error_of(console, "snapshot " + (dir / "s.png").string());
  EXPECT_NE(picture.find("log frame 10 is on the blackboard"), std::string::npos) << picture;
  EXPECT_FALSE(fs::exists(dir / "s.png"));
  console.execute("step");  // back to the simulation
  EXPECT_EQ(error_of(console, "get robot.torso.x"), "");
}

TEST_F(LogPointsTest, ExportTakesTheKeysGetTakes) {
  const fs::path csv = dir / "pitch.csv";
  console.execute("log export " + csv.string() +
                  " representation:InertialSensorData.angles[1] FrameInfo.time");
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "frame,InertialSensorData.angles[1],FrameInfo.time");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_GT(rows, 70);
  const std::string e =
      error_of(console, "log export " + csv.string() + " module:Stand.knee_pitch");
  EXPECT_NE(e.find("a log holds representations, not parameters"), std::string::npos) << e;
}

TEST_F(LogPointsTest, ReplayWithoutASceneSaysWhatItNeeds) {
  LocalTarget bare;
  std::ostringstream text;
  Interpreter robot_only(bare, text);
  robot_only.execute("log load " + log);
  const std::string e = error_of(robot_only, "log replay");
  EXPECT_NE(e.find("load a scene first"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos);
  robot_only.execute("load " + kScene);  // what it asked for: then it replays
  robot_only.execute("log replay");
  EXPECT_EQ(bare.get("log.mismatches"), "0");
}

}  // namespace
}  // namespace stride::console
