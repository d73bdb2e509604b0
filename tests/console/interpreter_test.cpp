// The interpreter against a LocalTarget on the controlled NAO scene: every command reaches the
// simulation or controller, errors are one line and change nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"
#include "robot/core/error.hpp"

namespace stride::console {
namespace {

namespace fs = std::filesystem;
const std::string kScene = STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml";

class InterpreterTest : public ::testing::Test {
 protected:
  void SetUp() override { console.execute("load " + kScene); }
  std::string run(const std::string& line) {
    out.str("");
    console.execute(line);
    return out.str();
  }
  std::string error_of(const std::string& line) {
    try {
      console.execute(line);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
  double number(const std::string& key) { return std::stod(target.get(key)); }
  fs::path temp(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("stride_console_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
  }

  LocalTarget target;
  std::ostringstream out;
  Interpreter console{target, out};
};

TEST_F(InterpreterTest, RunAndStepAdvanceTheSimulationClock) {
  const double dt = target.step_seconds();
  ASSERT_GT(dt, 0);
  run("run 0.05");
  EXPECT_NEAR(number("sim.time"), 0.05, 1e-12);
  run("step 7");
  EXPECT_EQ(number("sim.steps"), std::llround(0.05 / dt) + 7);
  run("step");
  EXPECT_EQ(number("sim.steps"), std::llround(0.05 / dt) + 8);
  run("reset");
  EXPECT_EQ(number("sim.time"), 0);
}

TEST_F(InterpreterTest, SetChangesParametersAllOrNothing) {
  run("set module:Stand knee_pitch=0.5 hip_pitch=-0.2");
  EXPECT_EQ(run("get module:Stand.knee_pitch"), "0.5\n");
  EXPECT_EQ(run("get module:Stand.hip_pitch"), "-0.2\n");
  // A bad second field or an out-of-range value leaves every field as it was.
  EXPECT_NE(error_of("set module:Stand knee_pitch=0.6 no_such_field=1"), "");
  EXPECT_NE(error_of("set module:Stand knee_pitch=0.7 hip_pitch=9"), "");
  EXPECT_NE(error_of("set module:Stand knee_pitch=abc"), "");
  EXPECT_EQ(run("get module:Stand.knee_pitch"), "0.5\n");
  EXPECT_EQ(run("get module:Stand.hip_pitch"), "-0.2\n");
}

// A legal but absurd gain is applied and noted; the shipped scene's own values are not.
TEST_F(InterpreterTest, AbsurdParametersAreNotedWhenLoadedAndWhenSet) {
  const std::string scene = STRIDE_SOURCE_DIR "/scenes/push/stand_balance.xml";
  EXPECT_EQ(run("load " + scene).find("note:"), std::string::npos);
  EXPECT_EQ(run("set module:AnkleBalance kp=10000"),
            "note: AnkleBalance: kp = 10000 1/s^2: a closed-loop frequency of 100 rad/s, faster "
            "than a 10 ms control loop follows (plausible up to 2500; Fig. 7.5 uses 72)\n");
  EXPECT_EQ(target.get("module:AnkleBalance.kp"), "10000");
  EXPECT_EQ(run("set module:AnkleBalance kp=72"), "");
}

TEST_F(InterpreterTest, GetShowsValuesAndTypeDescriptions) {
  run("run 0.1");
  const std::string description = run("get module:Stand ?");
  EXPECT_NE(description.find("knee_pitch"), std::string::npos);
  EXPECT_NE(description.find("rad"), std::string::npos);
  EXPECT_NE(run("get representation:JointRequest").find("position"), std::string::npos);
  EXPECT_NE(error_of("get representation:NoSuchThing"), "");
  EXPECT_NE(error_of("get robot.torso.height").find("unknown key 'robot.torso.height'"),
            std::string::npos);
}

TEST_F(InterpreterTest, ModuleRequestsListAndSwapProviders) {
  EXPECT_NE(run("mr ?").find("JointRequest: Stand"), std::string::npos);
  EXPECT_NE(run("mr JointRequest ?").find("available:"), std::string::npos);
  EXPECT_EQ(run("mr JointRequest default"), "JointRequest <- Stand\n");
  EXPECT_NE(error_of("mr JointRequest NoSuchModule"), "");
  EXPECT_NE(run("mr JointRequest ?").find("JointRequest: Stand"), std::string::npos);
}

TEST_F(InterpreterTest, ExpectComparesAndFailsWithTheActualValue) {
  run("run 0.2");
  run("expect robot.fell == false");
  run("expect sim.time ~= 0.2 1e-9");
  const std::string e = error_of("expect sim.time > 5");
  EXPECT_EQ(e.rfind("expect sim.time > 5 failed: actual 0.2", 0), 0u) << e;
}

TEST_F(InterpreterTest, WaitUntilStopsAtTheFirstStepThatSatisfiesTheCondition) {
  run("wait until sim.time >= 0.123");
  EXPECT_NEAR(number("sim.time"), 0.123, 1e-12);
  const std::string e = error_of("wait until sim.time < 0 timeout 0.01");
  EXPECT_NE(e.find("not reached within 0.01 s"), std::string::npos) << e;
  EXPECT_NEAR(number("sim.time"), 0.133, 1e-12);
}

// `every N` counts control frames, as on a remote robot (issue 49 point 8), not physics steps.
TEST_F(InterpreterTest, WatchPrintsEveryNControlFrames) {
  const std::uint64_t per = target.steps_per_frame();
  EXPECT_EQ(per, std::llround(0.01 / target.step_seconds()));  // the NAO v4 DCM's 10 ms
  ASSERT_GT(per, 1u);
  run("watch sim.steps every 3");
  const std::string printed = run("step " + std::to_string(3 * per * 3 + per));
  EXPECT_EQ(std::count(printed.begin(), printed.end(), '\n'), 3) << printed;
  EXPECT_NE(printed.find("sim.steps=" + std::to_string(3 * per) + "\n"), std::string::npos)
      << printed;
  run("watch off");
  EXPECT_EQ(run("step 20"), "");
  EXPECT_NE(error_of("watch robot.nothing"), "");
}

TEST_F(InterpreterTest, PlotRecordsEveryStepToCsv) {
  const fs::path csv = temp("plot.csv");
  run("plot robot.torso.z sim.steps to " + csv.string());
  run("step 25");
  run("plot stop");
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "t,robot.torso.z,sim.steps");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 25);
  EXPECT_NE(error_of("plot stop"), "");
}

TEST_F(InterpreterTest, MoveSensorSwitchesAndPush) {
  run("mv 1 -2 0.5 0.3");
  EXPECT_NEAR(number("robot.torso.x"), 1, 1e-9);
  EXPECT_NEAR(number("robot.torso.y"), -2, 1e-9);
  EXPECT_NEAR(number("robot.torso.z"), 0.5, 1e-9);
  EXPECT_NEAR(number("robot.torso.yaw"), 0.3, 1e-9);
  run("sn noise off");
  EXPECT_FALSE(target.session().simulation().robot(0).sensor_switches().noise);
  run("push torso 5 0 0 0.1");
  EXPECT_NE(error_of("push no_such_link 5 0 0 0.1"), "");
}

TEST_F(InterpreterTest, RobotSelectionListsAndRejectsUnknownNames) {
  EXPECT_EQ(run("robot"), "* nao\n");
  const std::string err = error_of("robot green");
  EXPECT_EQ(err, "no robot 'green' in this scene (robots: nao)");
  EXPECT_EQ(target.get("robot.name"), "nao");  // unchanged
  EXPECT_NE(error_of("robot a b").find("robot"), std::string::npos);
}

TEST_F(InterpreterTest, LogRecordReplayAndCompare) {
  const fs::path log = temp("stand.log");
  run("log start " + log.string());
  run("run 0.3");
  run("log stop");
  EXPECT_NE(error_of("log stop"), "");
  run("log load " + log.string());
  const int frames = static_cast<int>(number("log.frames"));
  EXPECT_GT(frames, 10);
  const std::string replay = run("log replay");
  EXPECT_NE(replay.find("0 mismatch(es)"), std::string::npos) << replay;
  EXPECT_EQ(number("log.mismatches"), 0);
  EXPECT_EQ(number("log.replayed"), frames);
  run("log goto 3");
  EXPECT_NE(error_of("log goto " + std::to_string(frames)).find("outside the log"),
            std::string::npos);
  const fs::path csv = temp("stand.csv");
  run("log export " + csv.string() + " FrameInfo.time");
  std::ifstream in(csv);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, frames + 1);
}

TEST_F(InterpreterTest, ReportWritesJsonWithTheStateHash) {
  run("run 0.05");
  const fs::path json = temp("report.json");
  run("report " + json.string());
  std::ifstream in(json);
  std::stringstream s;
  s << in.rdbuf();
  const std::string hash = target.get("sim.hash");
  EXPECT_EQ(hash.size(), 16u);
  EXPECT_NE(s.str().find("\"state_hash\""), std::string::npos) << s.str();
  EXPECT_NE(s.str().find("\"" + hash + "\""), std::string::npos) << s.str();
  // The wall time is the stepping's, not 0 (a real-time factor of 0 would be a false figure).
  const std::size_t wall = s.str().find("\"wall_time\":");
  ASSERT_NE(wall, std::string::npos) << s.str();
  EXPECT_GT(std::stod(s.str().substr(wall + 12)), 0.0) << s.str();
  EXPECT_NE(run("report").find("hash " + target.get("sim.hash")), std::string::npos);
}

TEST_F(InterpreterTest, ScriptErrorsNameFileAndLine) {
  const fs::path script = temp("bad.con");
  std::ofstream(script) << "# comment\necho one\nrnu 1\necho never\n";
  out.str("");
  const std::string e = error_of("call " + script.string());
  EXPECT_EQ(e, script.string() + ":3: unknown command 'rnu'; did you mean 'run'?");
  EXPECT_EQ(out.str(), "one\n");
}

TEST_F(InterpreterTest, SceneScriptRunsWhenTheSceneLoads) {
  // A copy of the scene with absolute robot paths, and a <scene>.con beside it.
  std::ifstream in(kScene);
  std::stringstream xml;
  xml << in.rdbuf();
  std::string text = xml.str();
  const std::string robots = STRIDE_SOURCE_DIR "/scenes/robots/";
  for (std::size_t at; (at = text.find("\"robots/")) != std::string::npos;)
    text.replace(at, 8, "\"" + robots);
  const fs::path scene = temp("with_script.xml");
  std::ofstream(scene) << text;
  std::ofstream(temp("with_script.con")) << "set module:Stand knee_pitch=0.4\necho scene script\n";
  const std::string printed = run("load " + scene.string());
  EXPECT_NE(printed.find("scene script"), std::string::npos) << printed;
  EXPECT_EQ(run("get module:Stand.knee_pitch"), "0.4\n");
}

TEST(InterpreterWithoutScene, CommandsThatNeedASceneSaySo) {
  LocalTarget target;
  std::ostringstream out;
  Interpreter console(target, out);
  EXPECT_TRUE(console.execute_reporting("echo hi"));
  EXPECT_FALSE(console.execute_reporting("run 1"));
  EXPECT_FALSE(console.execute_reporting("load /no/such/scene.xml"));
  EXPECT_NE(out.str().find("error: no scene loaded"), std::string::npos) << out.str();
  EXPECT_FALSE(target.loaded());
}

}  // namespace
}  // namespace stride::console
