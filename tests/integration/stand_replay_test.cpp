// The Stand scene under its controller: 10 s standing, logged; replaying the log through the same
// modules reproduces every representation bit for bit.
#include <filesystem>

#include <gtest/gtest.h>

#include "console/session/sim_session.hpp"
#include "robot/runtime/replay.hpp"

namespace stride {
namespace {

TEST(StandReplay, TenSecondsStandingReplaysBitForBit) {
  const std::string scene = std::string(STRIDE_SOURCE_DIR) + "/scenes/nao_stand_controlled.xml";
  const std::string log_path =
      (std::filesystem::temp_directory_path() / "stride_stand_replay_test.log").string();
  console::SimSession session(scene);
  ASSERT_NE(session.runtime(0), nullptr);
  session.runtime(0)->start_log(log_path);
  const auto p0 = session.simulation().robot(0).torso_pose();
  session.simulation().run_for(10.0);
  session.runtime(0)->stop_log();
  const auto p1 = session.simulation().robot(0).torso_pose();
  EXPECT_FALSE(session.simulation().robot(0).fallen());
  EXPECT_LT(std::hypot(p1.x - p0.x, p1.y - p0.y), 0.01);

  LogReader log(log_path);
  EXPECT_EQ(log.frame_count(), 1000u);  // 10 s at the 10 ms control period
  const ReplayResult r = replay_and_compare(log, session.registry(), session.runtime_config(0));
  EXPECT_EQ(r.frames, log.frame_count());
  EXPECT_GE(r.compared.size(), 6u);
  EXPECT_TRUE(r.mismatches.empty())
      << r.mismatches.size()
      << " mismatches, first: " << (r.mismatches.empty() ? "" : r.mismatches[0].representation);
  std::filesystem::remove(log_path);
}

}  // namespace
}  // namespace stride
