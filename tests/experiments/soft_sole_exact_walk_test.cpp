// On scenes/experiments/soft_sole_exact (rubber soles, 100/s leg servos, exact solver, Q rate
// 3e-5) posture control decides the medium walk of Sec. 4.3.4.2: without it the torso passes
// 0.4 rad or the robot falls; with either strategy it walks the 15 s upright and forward.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "console/experiments/posture_tally.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {
namespace {

WalkSummary walk(const std::string& scene) {
  const WalkSetup setup{
      std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/soft_sole_exact/" + scene + ".xml", 1};
  return summarize(record_walk(setup));
}

// The experiment's own criterion (fell or past 0.4 rad), as its per-case count applies it.
bool lost(const WalkSummary& s) {
  PostureTally t;
  add_walk(t, s);
  return t.lost() == 1;
}

TEST(SoftSoleExactWalk, WithoutPostureControlTheMediumWalkIsLost) {
  EXPECT_TRUE(lost(walk("none_medium")));
}

TEST(SoftSoleExactWalk, HipStrategyKeepsTheMediumWalk) {
  const WalkSummary s = walk("hip_medium");
  EXPECT_FALSE(lost(s));
  EXPECT_GT(s.fk_distance, 2.0);  // thesis Fig. 4.7: 2.88 m
  EXPECT_LT(std::max(-s.pitch_min, s.pitch_max), 0.2);
}

TEST(SoftSoleExactWalk, AnkleStrategyKeepsTheMediumWalk) {
  const WalkSummary s = walk("ankle_medium");
  EXPECT_FALSE(lost(s));
  EXPECT_GT(s.fk_distance, 2.0);  // thesis Fig. 4.11: 2.61 m
  EXPECT_LT(std::max(-s.pitch_min, s.pitch_max), 0.2);
}

}  // namespace
}  // namespace stride::experiments
