// `stride lola dump` against the simulator's LoLA, and `stride robot --log` stopped by SIGTERM:
// the real processes over a real unix socket.
#include <thread>

#include <gtest/gtest.h>

#include "robot/runtime/log.hpp"
#include "tests/lola/lola_test_support.hpp"

namespace stride {
namespace {

using test::ChildProcess;

TEST(LolaTools, DumpPrintsDecodedFramesFromTheSimulatorsLola) {
  const std::string socket = ChildProcess::scratch("dump.sock");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "0.5", "--lola", socket},
                   "dump_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess dump({test::kStride, "lola", "dump", socket, "--frames", "3"}, "dump");
  ASSERT_EQ(dump.wait_for(60), 0) << dump.err();
  const std::string out = dump.out();
  EXPECT_NE(out.find("frame 1  t 0.0000 s  robot P0000SIMULATEDBODY01 6.0.0"), std::string::npos)
      << out;
  EXPECT_NE(out.find("frame 3  t 0.0240 s"), std::string::npos) << out;
  EXPECT_EQ(out.find("frame 4 "), std::string::npos) << out;
  // The scene's initial knees (0.6 rad) as the 12-bit encoders read them, and LoLA's FSR order.
  const auto knee = out.find("LKneePitch ");
  ASSERT_NE(knee, std::string::npos) << out;
  EXPECT_NEAR(std::stod(out.substr(knee + 11)), 0.6, 0.01) << out;
  EXPECT_NE(out.find("fsr [N]: LFsrFL"), std::string::npos) << out;
  EXPECT_NE(dump.err().find("stride lola dump: 3 frames, 0 bad packets"), std::string::npos)
      << dump.err();
  sim.signal(SIGKILL);
}

TEST(LolaTools, RobotLogHoldsEveryFrameAfterSigterm) {
  const std::string socket = ChildProcess::scratch("log.sock");
  const std::string log = ChildProcess::scratch("robot.log");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "60", "--lola", socket},
                   "log_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot(
      {test::kStrideRobot, "--config", test::kHipConfig, "--lola", socket, "--log", log},
      "log_robot");
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  robot.signal(SIGTERM);
  ASSERT_EQ(robot.wait_for(20), 0) << robot.err();
  EXPECT_NE(robot.err().find("SIGTERM: stopped after a complete frame"), std::string::npos)
      << robot.err();
  const std::string out = robot.out();
  const auto at = out.find("frames ");
  ASSERT_NE(at, std::string::npos) << out;
  const std::size_t frames = std::stoul(out.substr(at + 7));
  EXPECT_GT(frames, 0u) << out;
  const LogReader reader(log);  // closed: every frame complete, nothing after the last
  EXPECT_EQ(reader.frame_count(), frames);
  EXPECT_FALSE(reader.truncated());
  EXPECT_GE(reader.index_of("JointRequest"), 0);
  sim.signal(SIGKILL);
}

}  // namespace
}  // namespace stride
