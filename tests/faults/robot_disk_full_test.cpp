// `stride robot --log` on a disk that fills: the child's files are bounded (RLIMIT_FSIZE, SIGXFSZ
// ignored), so the log's write fails with EFBIG as on a full disk. Documented outcome: one line
// "logging stopped: <why>", the frames written stay readable, and the control loop goes on
// answering every frame until SIGTERM and its summary.
#include <gtest/gtest.h>

#include "robot/runtime/log.hpp"
#include "tests/faults/fault_support.hpp"

namespace stride {
namespace {

using test::ChildProcess;
using test::number_after;

TEST(RobotDiskFull, LoggingStopsAndTheControlLoopGoesOn) {
  const std::string log = ChildProcess::scratch("disk_full.log");
  test::RobotOnFakeLola r("disk_full", "", {"--log", log}, 256 * 1024);
  ASSERT_TRUE(r.connected) << r.robot->err();
  auto& robot = *r.robot;
  const auto t = r.lola.serve(300, 0.012);
  EXPECT_FALSE(t.peer_closed) << robot.err();
  ASSERT_EQ(r.stop(), 0) << robot.err();  // not SIGABRT: the loop outlived the disk
  const std::string err = robot.err(), out = robot.out();
  const std::string line = "logging stopped: cannot write '" + log + "': File too large";
  const auto at = err.find(line);
  ASSERT_NE(at, std::string::npos) << err;
  EXPECT_EQ(err.find(line, at + 1), std::string::npos) << "one line, not one per frame: " << err;
  EXPECT_NE(err.find("(the control loop goes on)"), std::string::npos) << err;
  // Every packet read (a frame late on a busy machine may skip one as stale).
  EXPECT_EQ(number_after(out, "frames ") + number_after(out, "stale skipped "), 300) << out;
  const long logged = number_after(out, "log: stopped after ");
  ASSERT_GT(logged, 0) << out;
  EXPECT_LT(logged, 300) << out;
  // What was written before the disk filled reads back whole.
  const LogReader reader(log);
  EXPECT_EQ(reader.integrity().complete, static_cast<std::size_t>(logged)) << reader.summary();
  EXPECT_EQ(reader.integrity().damaged, 0u) << reader.summary();
  // A stopped loop misses every frame; a busy machine (CI runs two tests at once) misses some.
  EXPECT_LT(t.missed, 150) << "frames the fake LoLA saw unanswered in time";
  test::print_fault_row("disk full under --log (256 KiB file limit)", t.missed, t.sent,
                        "logging stopped after " + std::to_string(logged) +
                            " frames (one line), loop ran to SIGTERM, summary, exit 0");
}

}  // namespace
}  // namespace stride
