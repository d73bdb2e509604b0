// Sec. 4.4's purpose, measured: at the fastest of Fig. 4.18's speeds the arm swing of Eq. 4.20
// takes yaw moment off the support foot, which then turns less per stance.
#include <gtest/gtest.h>

#include "console/experiments/arm_swing_experiment.hpp"

namespace stride::experiments {
namespace {

double foot_turn_per_step(bool swing, std::uint64_t seed) {
  ExperimentOptions o;
  o.scenes_dir = std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments";
  const WalkRecording r = record_walk(arm_swing_walk(o, 0.1940, swing, seed));
  const WalkSummary s = summarize(r);
  EXPECT_FALSE(s.fell);
  EXPECT_GT(s.steps, 70);
  return r.metrics.foot_spin / s.steps;
}

TEST(ArmSwingYaw, SwingCutsTheSupportFootTurnAtTheHighSpeed) {
  const double on = foot_turn_per_step(true, 1), off = foot_turn_per_step(false, 1);
  RecordProperty("turn_per_step_on_mrad", std::to_string(1000 * on));
  RecordProperty("turn_per_step_off_mrad", std::to_string(1000 * off));
  EXPECT_LT(on, 0.8 * off);  // 6 seeds: 29 against 48 mrad per step
}

}  // namespace
}  // namespace stride::experiments
