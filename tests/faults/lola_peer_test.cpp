// LoLA peers that misbehave, each against the real `stride-robot` over a real unix socket: one
// that stops reading, one that sends slowly, one that floods, one whose packets are a byte short.
// The documented outcome of each: the control loop is never blocked; a peer that takes no answer
// is a lost link (the one-line report, the held command, exit 2 after link_timeout); the rest
// keep the loop running to SIGTERM and its summary.
#include <gtest/gtest.h>

#include "tests/faults/fault_support.hpp"

namespace stride {
namespace {

using test::ChildProcess;
using test::number_after;

TEST(LolaPeerFaults, PeerThatStopsReadingIsALostLinkNotABlockedLoop) {
  test::RobotOnFakeLola r("stops_reading", "link_timeout=\"0.5s\"");
  ASSERT_TRUE(r.connected) << r.robot->err();
  auto& lola = r.lola;
  auto& robot = *r.robot;
  const auto before = lola.serve(50, 0.012);
  EXPECT_EQ(before.sent, 50);
  // Packets go on, answers pile up unread until the robot's socket buffer is full (12 s at most).
  const auto stopped = std::chrono::steady_clock::now();
  const auto after = lola.serve(1000, 0.012, false);
  const auto code = robot.wait_for(10);
  const double lost_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - stopped).count();
  ASSERT_EQ(code, 2) << "the robot blocked in a write: " << robot.err();
  const std::string err = robot.err(), out = robot.out();
  EXPECT_NE(err.find("LoLA link lost (the peer took no answer for 12 ms: it stopped reading)"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("holding the last command; exiting if it is not back within 0.5 s"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("no LoLA link for "), std::string::npos) << err;
  EXPECT_NE(out.find("unsent answers 1"), std::string::npos) << out;  // summary printed
  const long frames = number_after(out, "frames ");
  EXPECT_GE(frames, 50) << out;
  test::print_fault_row("peer stops reading", after.sent - static_cast<int>(frames - 50),
                        after.sent,
                        "answers taken into the socket buffer for " + std::to_string(frames - 50) +
                            " frames, then link lost; exit 2 " +
                            std::to_string(lost_s).substr(0, 4) + " s after reading stopped");
}

TEST(LolaPeerFaults, PeerThatSendsSlowlyKeepsTheLoopRunning) {
  test::RobotOnFakeLola r("slow", "");
  ASSERT_TRUE(r.connected) << r.robot->err();
  auto& lola = r.lola;
  auto& robot = *r.robot;
  // Each packet dribbled in 8 pieces over 8 ms; then a peer at 20 ms instead of 12 ms.
  const auto dribbled = lola.serve(100, 0.012, true, 8, 0.008);
  const auto slower = lola.serve(50, 0.020);
  ASSERT_EQ(r.stop(), 0) << robot.err();
  const std::string out = robot.out();
  // Every packet read whole (none bad); a frame late on a busy machine may skip one as stale.
  EXPECT_EQ(number_after(out, "LoLA packets "), 150) << out;
  EXPECT_EQ(number_after(out, "frames ") + number_after(out, "stale skipped "), 150) << out;
  EXPECT_EQ(number_after(out, "(bad "), 0) << out;
  // A blocked loop would miss them all; a busy machine (CI runs two tests at once) misses some.
  EXPECT_LT(dribbled.missed + slower.missed, 75) << out;
  test::print_fault_row(
      "peer sends slowly (8 pieces over 8 ms)", dribbled.missed, dribbled.sent,
      "every packet answered; stalls " + std::to_string(number_after(out, "stalls ")));
  test::print_fault_row("peer at 20 ms instead of 12 ms", slower.missed, slower.sent,
                        "every packet answered, loop runs to SIGTERM (exit 0)");
}

TEST(LolaPeerFaults, PeerThatFloodsIsAnsweredNewestFirst) {
  test::RobotOnFakeLola r("flood", "");
  ASSERT_TRUE(r.connected) << r.robot->err();
  auto& lola = r.lola;
  auto& robot = *r.robot;
  const auto flood = lola.flood(3000);
  const auto calm = lola.serve(20, 0.012);  // the robot caught up: answers every frame again
  ASSERT_EQ(r.stop(), 0) << robot.err();
  const std::string out = robot.out();
  ASSERT_EQ(flood.sent, 3000);
  // Every packet read and counted once; a frame runs on the newest, older ones are skipped.
  const long frames = number_after(out, "frames "), stale = number_after(out, "stale skipped ");
  EXPECT_EQ(number_after(out, "LoLA packets "), 3020) << out;
  EXPECT_EQ(frames + stale, 3020) << out;
  EXPECT_GE(calm.answered, 10) << out;  // a loop still drowning would answer none in time
  test::print_fault_row("peer floods (3000 packets back to back)", 0, flood.sent,
                        std::to_string(frames) + " frames ran, " + std::to_string(stale) +
                            " stale packets skipped; then " + std::to_string(calm.missed) +
                            " of 20 paced frames missed");
}

// The 895-byte packets: each a byte short, so the next packet's first byte completes it
// and the rest of that packet is the middle of a map. Counted as packets, not as msgpack values
// (the stream is dropped where a value is not a map); none is valid, so the link is silent.
TEST(LolaPeerFaults, PacketsAByteShortAreCountedOncePerPacket) {
  test::RobotOnFakeLola r("short", "link_timeout=\"10s\"");
  ASSERT_TRUE(r.connected) << r.robot->err();
  auto& lola = r.lola;
  auto& robot = *r.robot;
  const std::string short_packet = lola.packet().substr(0, lola.packet().size() - 1);
  ASSERT_EQ(short_packet.size(), 895u);
  const auto t = lola.serve(250, 0.012, true, 1, 0, &short_packet);
  ASSERT_EQ(t.sent, 250);
  ASSERT_EQ(r.stop(), 0) << robot.err();
  const std::string out = robot.out();
  const long packets = number_after(out, "LoLA packets ");
  EXPECT_LE(packets, 250) << out;
  EXPECT_GE(packets, 125) << out;
  EXPECT_GE(number_after(out, "(bad "), 1) << out;
  EXPECT_EQ(number_after(out, "frames "), 0) << out;  // no packet decoded: every frame held
  EXPECT_NE(out.find("do not start a msgpack map"), std::string::npos) << out;
  EXPECT_NE(robot.err().find("LoLA link silent"), std::string::npos) << robot.err();
}

}  // namespace
}  // namespace stride
