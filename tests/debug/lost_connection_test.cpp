// A connection lost from either end, with real processes: a robot that dies under a console's
// script is one line naming it and the script's run-failure exit code, at once; a console that
// dies under a robot leaves the robot's loop running and its server serving the next console.
#include <chrono>
#include <iostream>
#include <thread>

#include <gtest/gtest.h>

#include "robot/debug/debug_client.hpp"
#include "tests/debug/robot_loop.hpp"
#include "tests/lola/lola_test_support.hpp"

namespace stride::test {
namespace {

const std::string kStandScene = STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml";

// Waits (bounded) until `text()` holds `part`.
template <class Text>
bool shows(Text&& text, const std::string& part, double seconds = 60) {
  for (int i = 0; i < seconds * 100; ++i) {
    if (text().find(part) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

std::string endpoint_in(const std::string& out) {
  const std::string marker = "debug server on ";
  const auto at = out.find(marker);
  if (at == std::string::npos) return "";
  const auto begin = at + marker.size();
  return out.substr(begin, out.find_first_of(" \n", begin) - begin);
}

TEST(LostConnection, RobotKilledUnderAScriptIsOneLineAndExitOne) {
  ChildProcess sim({kStride, "run", kStandScene, "--seconds", "120", "--debug", "127.0.0.1:0"},
                   "lost_sim");
  ASSERT_TRUE(shows([&] { return sim.out(); }, "debug server on ")) << sim.err();
  const std::string at = endpoint_in(sim.out());
  ChildProcess console(
      {kStride, "--connect", at, "-c", "watch representation:FrameInfo.frame; run 60"},
      "lost_console");
  // The console is streaming frames when the robot goes.
  ASSERT_TRUE(shows([&] { return console.out(); }, "representation:FrameInfo.frame="))
      << console.err();
  sim.signal(SIGKILL);
  const auto killed = std::chrono::steady_clock::now();
  const std::optional<int> code = console.wait_for(20);
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - killed).count();
  ASSERT_TRUE(code.has_value()) << "the console hung after its robot died";
  EXPECT_EQ(*code, 1);  // a run failure, as a failed expect
  std::cout << "the console ended " << took << " s after its robot was killed\n";
  const std::string err = console.err();
  EXPECT_EQ(err.find('\n'), err.size() - 1) << err;  // one line
  EXPECT_NE(err.find("-c:2: lost the connection to " + at + ": "), std::string::npos) << err;
  EXPECT_NE(err.find("connect again to resume"), std::string::npos) << err;
}

TEST(LostConnection, ConsoleKilledMidStreamLeavesTheLoopRunning) {
  RobotLoop loop(loopback_options());
  ChildProcess console({kStride, "--connect", loop.endpoint().text(), "-c",
                        "watch representation:Counter.n; run 60"},
                       "vanishing_console");
  ASSERT_TRUE(shows([&] { return console.out(); }, "representation:Counter.n=")) << console.err();
  const std::int64_t frames_before = loop.frames();
  console.signal(SIGKILL);
  ASSERT_TRUE(console.wait_for(10).has_value());
  for (int i = 0; i < 1000 && loop.log_count("disconnected: ") == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(loop.log_count("disconnected: "), 1u);
  // The loop went on, and the next console is served (a stream of frames that follow on).
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_GT(loop.frames(), frames_before + 10);
  debug::DebugClient next(loop.endpoint(), "");
  debug::Request sub = debug::request(debug::Op::Subscribe);
  sub.keys = {"representation:Counter.n"};
  const std::int64_t from = next.call(sub)->fields().integer("from");
  const auto sample = next.next_sample(5);
  ASSERT_TRUE(sample.has_value());
  EXPECT_GE(sample->frame, from);
  EXPECT_EQ(loop.server().stats().clients, 1u);
  std::cout << "frames " << loop.frames() << ", late " << loop.late_frames()
            << ", longest exchange " << loop.longest_boundary_seconds() * 1e3
            << " ms (reported, not judged: the machine is shared)\n";
}

}  // namespace
}  // namespace stride::test
