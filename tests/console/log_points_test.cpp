// Issue 49 point 6: after `log goto`, robot.torso.* and `snapshot` show the logged frame: a
// simulation's log records the torso's world pose, so x/y/z/roll/pitch/yaw are the logged ones and
// the picture is the logged robot where it stood; a log without a pose (a robot's, or one recorded
// before the pose was) gives roll/pitch from its IMU, refuses the rest in one line naming why,
// and draws the robot on its lowest point. `log export` takes the keys `get` takes; `log replay`
// without a scene says what it needs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"
#include "robot/core/error.hpp"
#include "simulator/render/image.hpp"
#include "simulator/render/png_file.hpp"

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

// Share of pixels below the text overlay (rows from 80) that two pictures have alike.
double alike_below_overlay(const std::string& a_path, const std::string& b_path) {
  const render::RgbaImage a = render::read_png(a_path), b = render::read_png(b_path);
  if (a.width != b.width || a.height != b.height) return 0;
  std::size_t same = 0, all = 0;
  for (int y = 80; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x, ++all) {
      const std::uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
      bool equal = true;
      for (int c = 0; c < 3; ++c) equal &= std::abs(int(p[c]) - int(q[c])) < 8;
      same += equal;
    }
  return static_cast<double>(same) / static_cast<double>(all);
}

TEST_F(LogPointsTest, GotoShowsTheLoggedTorsoPoseAndPicture) {
  const std::string live_end = target.get("robot.torso.y");
  console.execute("log goto 20");
  // The same scene, run live to the logged frame's time: what the log recorded there.
  const std::string logged_time = target.get("representation:FrameInfo.time");
  LocalTarget twin_target;
  std::ostringstream twin_out;
  Interpreter twin{twin_target, twin_out};
  twin.execute("load " + kScene);
  twin.execute("run " + logged_time);
  twin.execute("snapshot " + (dir / "live20.png").string() + " front");
  EXPECT_NE(out.str().find("frame 20 on the blackboard, the robot where the log puts it"),
            std::string::npos)
      << out.str();
  for (const char* k : {"robot.torso.x", "robot.torso.y", "robot.torso.z", "robot.torso.roll",
                        "robot.torso.pitch", "robot.torso.yaw"})
    EXPECT_NEAR(std::stod(target.get(k)), std::stod(twin_target.get(k)), 1e-9) << k;
  EXPECT_NE(target.get("robot.torso.y"), live_end);
  console.execute("snapshot " + (dir / "log20.png").string() + " front");
  console.execute("log goto 70");  // pushed: rolled and moved
  console.execute("snapshot " + (dir / "log70.png").string() + " front");
  const double same =
      alike_below_overlay((dir / "log20.png").string(), (dir / "live20.png").string());
  const double pushed =
      alike_below_overlay((dir / "log70.png").string(), (dir / "log20.png").string());
  EXPECT_GT(same, 0.995) << "the picture of log frame 20 is not the robot as it stood then";
  EXPECT_LT(pushed, same - 0.002) << "log frame 70's picture shows no other robot than frame 20's";
  EXPECT_EQ(error_of(console, "get robot.com.x").find("a log holds the torso's pose only"),
            std::string("robot.com.x: log frame 70 is shown and ").size());
  console.execute("step");  // back to the simulation
  EXPECT_EQ(error_of(console, "get robot.com.x"), "");
}

// A log from before the pose was recorded (the fuzz corpus's, committed then): it loads, its IMU
// gives roll and pitch, the rest is refused saying why, and the picture stands the robot up.
TEST_F(LogPointsTest, ALogWithoutAWorldPoseSaysSoAndStillDraws) {
  console.execute("log load " STRIDE_SOURCE_DIR "/tests/fuzz_log/corpus/strdlog2_nao_stand.log");
  console.execute("log goto 2");
  EXPECT_NE(out.str().find("frame 2 on the blackboard"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("; this log holds no world pose (a robot's, or recorded before "
                           "2026-12-06): snapshot stands the robot on its lowest point"),
            std::string::npos)
      << out.str();
  EXPECT_EQ(target.get("robot.torso.roll"),
            target.get("representation:InertialSensorData.angles[0]"));
  EXPECT_EQ(target.get("robot.torso.pitch"),
            target.get("representation:InertialSensorData.angles[1]"));
  const std::string x = error_of(console, "expect robot.torso.x > 0");
  EXPECT_NE(x.find("log frame 2 is shown and this log holds no world pose (a robot's, or a "
                   "simulation's recorded before 2026-12-06"),
            std::string::npos)
      << x;
  console.execute("snapshot " + (dir / "old.png").string() + " front");
  EXPECT_GT(fs::file_size(dir / "old.png"), 1000u);
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
