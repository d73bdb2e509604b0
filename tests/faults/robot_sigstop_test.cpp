// The process on the other side stopped (SIGSTOP) and continued: the simulator serving LoLA, and
// a console connected to the robot's debug server while it streams. Documented outcome: a
// stopped LoLA is a silent link (reported within a frame, the command held, "back" when it
// resumes); a stopped console costs the control loop nothing.
#include <algorithm>

#include <gtest/gtest.h>

#include "tests/faults/fault_support.hpp"

namespace stride {
namespace {

using test::ChildProcess;
using test::number_after;

// The simulator on the wall clock (--realtime), stopped for 0.3 s mid-run: the frames it could not
// send are the frames missed; when it resumes late it sends the packets it owes back to back and
// the robot answers the newest.
TEST(RobotSigstop, StoppedSimulatorIsASilentLinkAndTheLoopResumesWithIt) {
  const std::string socket = ChildProcess::scratch("sigstop_sim.sock");
  const std::string report = ChildProcess::scratch("sigstop_sim.json");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "3", "--lola", socket,
                    "--realtime", "--report", report},
                   "sigstop_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot({test::kStrideRobot, "--config",
                      test::stand_config("sigstop_sim", "link_timeout=\"1s\""), "--lola", socket},
                     "sigstop_sim_robot");
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  sim.signal(SIGSTOP);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  sim.signal(SIGCONT);
  ASSERT_EQ(sim.wait_for(120), 0) << sim.err();
  ASSERT_EQ(robot.wait_for(10), 2) << robot.err();  // the simulator ended: the link is gone
  const std::string err = robot.err(), out = robot.out(), json = test::read_file(report);
  ASSERT_NE(err.find("LoLA link silent"), std::string::npos) << err;
  // The longest silence: a simulator slower than the wall clock (ASan) adds short ones.
  double gap_ms = 0;
  for (auto back = err.find("LoLA link back after "); back != std::string::npos;
       back = err.find("LoLA link back after ", back + 1))
    gap_ms = std::max(gap_ms, std::stod(err.substr(back + 21)));
  EXPECT_GE(gap_ms, 250.0) << err;
  EXPECT_LT(gap_ms, 1000.0) << err;
  EXPECT_NE(err.find("no LoLA link for "), std::string::npos) << err;
  const long frames = number_after(out, "frames "), stale = number_after(out, "stale skipped ");
  const int sent = std::stoi(test::json_value(json, "frames"));
  EXPECT_EQ(sent, 250) << json;            // 3 s of 12 ms frames
  EXPECT_EQ(frames + stale, sent) << out;  // every packet read; the owed ones mostly skipped
  test::print_fault_row("SIGSTOP of the simulator for 0.3 s (--realtime LoLA)",
                        std::stoi(test::json_value(json, "missed")), sent,
                        "no packet for " + std::to_string(static_cast<int>(gap_ms)) + " ms (" +
                            std::to_string(static_cast<int>(gap_ms / 12)) +
                            " periods): silent within a frame, command held, back on SIGCONT; " +
                            std::to_string(stale) + " owed packets skipped as stale");
}

// The robot stopped (SIGSTOP) for good while the simulator serves it on the wall clock: once the
// socket's buffer is full the simulator's sends are bounded too, so it loses the client ("it
// stopped reading") and ends its run on time instead of blocking in a write.
TEST(RobotSigstop, StoppedRobotIsALostClientAndTheSimulatorEndsOnTime) {
  const std::string socket = ChildProcess::scratch("sigstop_robot.sock");
  const std::string report = ChildProcess::scratch("sigstop_robot.json");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "4", "--lola", socket,
                    "--realtime", "--report", report},
                   "sigstop_robot_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot({test::kStrideRobot, "--config",
                      test::stand_config("sigstop_robot", "link_timeout=\"1s\""), "--lola", socket},
                     "sigstop_robot_robot");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  robot.signal(SIGSTOP);
  const auto code = sim.wait_for(30);  // 4 s of run; blocked for good before the bound
  robot.signal(SIGCONT);
  ASSERT_EQ(code, 0) << sim.err();
  const std::string json = test::read_file(report), err = sim.err() + sim.out();
  EXPECT_EQ(std::stoi(test::json_value(json, "clients_lost")), 1) << json;
  EXPECT_NE(err.find("stopped reading"), std::string::npos) << err;
}

TEST(RobotSigstop, StoppedConsoleCostsTheControlLoopNothing) {
  // --no-wait: the controller runs from the start, so the quiet phase measures its loop alone.
  test::RobotOnFakeLola r(
      "sigstop_console", "",
      {"--debug", "127.0.0.1:0", "--no-wait", "--log-dir", ChildProcess::scratch("")});
  ASSERT_TRUE(r.connected) << r.robot->err();
  auto& lola = r.lola;
  auto& robot = *r.robot;
  const auto quiet = lola.serve(250, 0.012);  // the same 3 s with no console: the machine's share
  const std::string at = test::debug_endpoint(robot, 10);
  ASSERT_FALSE(at.empty()) << robot.err();
  ChildProcess console({test::kStride, "--connect", at, "-c",
                        "watch representation:JointRequest.position every 1; run 60"},
                       "sigstop_console");
  const auto streaming = lola.serve(100, 0.012);  // the console connects and streams meanwhile
  console.signal(SIGSTOP);
  const auto stopped = lola.serve(250, 0.012);  // 3 s with a console that reads nothing
  console.signal(SIGCONT);
  console.signal(SIGKILL);
  EXPECT_EQ(console.wait_for(10), 128 + SIGKILL);
  const auto after = lola.serve(25, 0.012);
  ASSERT_EQ(r.stop(), 0) << robot.err();
  EXPECT_NE(console.out().find("connected"), std::string::npos) << console.out() << console.err();
  EXPECT_EQ(stopped.sent, 250);
  // A loop waiting on the console would miss all 250; a busy machine (CI runs two tests at once)
  // misses some whatever the console does.
  EXPECT_LT(stopped.missed, 125) << robot.err();
  EXPECT_EQ(number_after(robot.out(), "frames ") + number_after(robot.out(), "stale skipped "), 625)
      << robot.out();
  test::print_fault_row("SIGSTOP of a streaming console for 3 s", stopped.missed, stopped.sent,
                        "loop unaffected (" + std::to_string(quiet.missed) +
                            " of 250 missed with no console, " + std::to_string(streaming.missed) +
                            " of 100 while it streamed, " + std::to_string(after.missed) +
                            " of 25 after it was killed)");
}

}  // namespace
}  // namespace stride
