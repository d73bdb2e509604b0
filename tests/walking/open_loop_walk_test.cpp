// Open-loop walks in the simulator (thesis Sec. 4.3.4.2 without feedback): the medium-speed
// stretched-knee walk on flat ground swings the thesis' 61 steps in 15 s without falling; on the
// floor with local unevenness the torso inclines further, the reason for Ch. 4's posture control.
// The open-loop walk is chaotic: 1e-14 rad in the joint commands or a start 1-7 ms later changes
// the distance by a few percent, and 2 of 8 such starts of the medium walk fall (the knee servos
// lag, see scenes/walking/open_loop_slow.xml). These tests pin the scene's own trajectory.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "console/session/sim_session.hpp"

namespace stride {
namespace {

constexpr double kStartDelay = 2.0;  // WalkParameters default, as the scenes leave it

sim::WalkMetricsResult walk(const std::string& scene, double seconds) {
  console::SimSession session(std::string(STRIDE_SOURCE_DIR) + "/scenes/walking/" + scene);
  session.simulation().run_for(seconds);
  return session.simulation().walk_metrics(0).result();
}

double inclination_span(const sim::WalkMetricsResult& r) {
  return std::max(r.pitch_max - r.pitch_min, r.roll_max - r.roll_min);
}

class OpenLoopWalk : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const walking::StretchedKneePattern pattern(walking::preset("medium"));
    duration_ = pattern.duration();
    planned_distance_ = pattern.sample(duration_).waist.x();
    // Up to the last landing: after the stop the robot rocks and unloads a foot a few times,
    // which the FSR step count would take for steps.
    const double seconds = kStartDelay + duration_ + 0.05;
    flat_ = walk("open_loop_medium.xml", seconds);
    uneven_ = walk("open_loop_medium_uneven.xml", seconds);
  }
  static inline double duration_ = 0, planned_distance_ = 0;
  static inline sim::WalkMetricsResult flat_, uneven_;
};

TEST_F(OpenLoopWalk, FlatWalkTakesTheThesisStepsInFifteenSecondsAndStaysUp) {
  EXPECT_DOUBLE_EQ(duration_, 15.0);  // 60 waist steps of T_stride / 2 = 0.25 s
  EXPECT_FALSE(flat_.fell) << "fell at " << flat_.fell_at << " s";
  // The feet swing steps + 1 = 61 times (Sec. 4.3.4.2); the FSRs see 57 of them end in a double
  // support after a single one. 61 came with the 1 ms step's artefact of the law's split by count;
  // split by depth the walk converges at 1 ms and counts 56 ± 3 over 16 perturbed starts, as it
  // does at 0.25 ms (scenes/experiments/README.md, "engines agree").
  EXPECT_EQ(flat_.steps, 57);
  // Open loop on a slipping floor: forward, but not beyond the plan.
  EXPECT_GT(flat_.true_distance, 0.5 * planned_distance_);
  EXPECT_LT(flat_.true_distance, 1.1 * planned_distance_);
  EXPECT_GT(flat_.fk_distance, 0.5 * planned_distance_);
}

TEST_F(OpenLoopWalk, UnevenFloorInclinesTheTorsoMoreThanFlatGround) {
  EXPECT_GT(inclination_span(uneven_), inclination_span(flat_))
      << "flat pitch [" << flat_.pitch_min << ", " << flat_.pitch_max << "] roll ["
      << flat_.roll_min << ", " << flat_.roll_max << "], uneven pitch [" << uneven_.pitch_min
      << ", " << uneven_.pitch_max << "] roll [" << uneven_.roll_min << ", " << uneven_.roll_max
      << "]";
}

}  // namespace
}  // namespace stride
