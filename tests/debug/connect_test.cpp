// `connect` end to end with the real processes over loopback TCP: the same .con script runs
// against the local simulation, against `stride run <scene> --debug` and against `stride robot
// --debug` driving the simulated NAO over LoLA, and its get/expect lines read the same.
#include <filesystem>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "tests/debug/served_process.hpp"
#include "tests/lola/lola_test_support.hpp"

namespace stride {
namespace {

using test::ChildProcess;
using test::fresh_dir;
using test::served_endpoint;

const std::string kStandScene = STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml";
const std::string kScript = STRIDE_SOURCE_DIR "/tests/debug/scripts/stand_remote.con";
const std::string kFailing = STRIDE_SOURCE_DIR "/tests/debug/scripts/stand_remote_fails.con";

// The script's output without the lines that depend on where and when it ran: the greeting
// (loaded/connected), watch lines, the time a wait was reached, how a log was saved (copied or
// downloaded) and how many frames it holds (the robot's clock is the wall clock).
std::string comparable(const std::string& out) {
  std::istringstream in(out);
  std::string kept;
  for (std::string line; std::getline(in, line);)
    if (!line.starts_with("loaded ") && !line.starts_with("connected ") &&
        !line.starts_with("t=") && !line.starts_with("reached at t=") &&
        !line.starts_with("saved ") && !line.starts_with("downloaded ") &&
        !line.starts_with("stand_remote_copy.log: ") && !line.starts_with("ok log.frames = "))
      kept += line + "\n";
  return kept;
}

struct ScriptRun {
  int code = -1;
  std::string out, err;
};

// Runs in a fresh directory named `name`, where the script's logs go.
ScriptRun run_script(const std::vector<std::string>& argv, const std::string& name) {
  ChildProcess p(argv, name, fresh_dir(name));
  ScriptRun r;
  r.code = p.wait_for(120).value_or(-1);
  r.out = comparable(p.out());
  r.err = p.err();
  return r;
}

TEST(Connect, ScriptReadsTheSameLocallyAndAgainstStrideRunDebug) {
  const ScriptRun local = run_script({test::kStride, "--script", kScript, kStandScene}, "local");
  ASSERT_EQ(local.code, 0) << local.err;
  EXPECT_NE(local.out.find("ok module:Stand.knee_pitch = 0.8\n"), std::string::npos) << local.out;

  const std::string robot_logs = fresh_dir("sim_logs");
  ChildProcess sim({test::kStride, "run", kStandScene, "--seconds", "120", "--debug", "127.0.0.1:0",
                    "--log-dir", robot_logs},
                   "debug_sim");
  const std::string at = served_endpoint(sim, false);
  ASSERT_FALSE(at.empty()) << sim.out() << sim.err();
  const ScriptRun remote =
      run_script({test::kStride, "--script", kScript, "--connect", at}, "remote");
  ASSERT_EQ(remote.code, 0) << remote.err;
  EXPECT_EQ(remote.out, local.out);
  // The log recorded on the robot arrived byte for byte.
  const std::string recorded = test::read_file(robot_logs + "/stand_remote.log");
  EXPECT_GT(recorded.size(), 1000u);
  EXPECT_EQ(test::read_file(ChildProcess::scratch("remote") + "/stand_remote_copy.log"), recorded);

  // A failing expect fails the script the same way: exit 1, the same file:line message.
  const ScriptRun local_fail =
      run_script({test::kStride, "--script", kFailing, kStandScene}, "local_fail");
  const ScriptRun remote_fail =
      run_script({test::kStride, "--script", kFailing, "--connect", at}, "remote_fail");
  EXPECT_EQ(local_fail.code, 1);
  EXPECT_EQ(remote_fail.code, 1);
  EXPECT_NE(local_fail.err.find("stand_remote_fails.con:5: expect module:Stand.knee_pitch == 0.7 "
                                "failed: actual 0.6"),
            std::string::npos)
      << local_fail.err;
  EXPECT_EQ(remote_fail.err, local_fail.err);
  EXPECT_EQ(remote_fail.out, local_fail.out);

  // Simulation-only commands answer one line on a remote robot; robot commands still work.
  const ScriptRun mixed =
      run_script({test::kStride, "--connect", at, "-c", "push Torso 1 0 0 0.1"}, "remote_push");
  EXPECT_EQ(mixed.code, 1);
  EXPECT_NE(mixed.err.find("push"), std::string::npos) << mixed.err;
  EXPECT_EQ(mixed.err.find('\n'), mixed.err.size() - 1) << mixed.err;

  sim.signal(SIGTERM);
  EXPECT_EQ(sim.wait_for(30), 0) << sim.err();
}

TEST(Connect, ScriptReadsTheSameAgainstStrideRobotOnLola) {
  const std::string socket = ChildProcess::scratch("connect.sock");
  ChildProcess sim(
      {test::kStride, "run", kStandScene, "--seconds", "120", "--lola", socket, "--realtime"},
      "connect_lola_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  const std::string config = test::robot_config(
      "connect_stand",
      test::kStandController + "<parameter module=\"Stand\" field=\"stiffness\" value=\"1\"/>", "");
  ChildProcess robot({test::kStrideRobot, "--config", config, "--lola", socket, "--debug",
                      "127.0.0.1:0", "--log-dir", fresh_dir("robot_logs")},
                     "connect_robot");
  const std::string at = served_endpoint(robot, true);
  ASSERT_FALSE(at.empty()) << robot.err();

  const ScriptRun local = run_script({test::kStride, "--script", kScript, kStandScene}, "local2");
  ASSERT_EQ(local.code, 0) << local.err;
  const ScriptRun remote =
      run_script({test::kStride, "--script", kScript, "--connect", at}, "remote_robot");
  ASSERT_EQ(remote.code, 0) << remote.err << robot.err();
  EXPECT_EQ(remote.out, local.out);

  robot.signal(SIGTERM);
  EXPECT_EQ(robot.wait_for(30), 0) << robot.err();
  sim.signal(SIGKILL);
}

}  // namespace
}  // namespace stride
