// The WalkPlan the walking modules provide: the pattern's ZMP reference and feet at the sampled
// time, and the landings of the next swings in order, sides alternating, ahead of the feet; in a
// Runtime it is on the blackboard every frame, following the pattern at FrameInfo time.
#include <gtest/gtest.h>

#include "behaviours/module_catalogue.hpp"
#include "behaviours/walking/modules/walk_plan.hpp"
#include "behaviours/walking/pattern/adjusted_pattern.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"

namespace stride {
namespace {

using walking::Foot;
using walking::StretchedKneePattern;

TEST(WalkPlan, ZmpFeetAndTheNextLandingsOfThePattern) {
  const StretchedKneePattern pattern(walking::preset("medium"));
  const auto& feet = pattern.footsteps();
  const double T_step = pattern.parameters().T_step();
  for (double t : {0.0, 1.3, 5.0 * T_step + 0.01, pattern.duration() - 0.1, pattern.duration()}) {
    const walking::PatternSample s = pattern.sample(t);
    const WalkPlan p = walking::walk_plan(s, feet, t);
    EXPECT_EQ(p.t, t);
    EXPECT_EQ(p.zmp[0], s.zmp.x());
    EXPECT_EQ(p.zmp[1], s.zmp.y());
    EXPECT_EQ(p.support, static_cast<std::int64_t>(s.support));
    EXPECT_EQ(p.left_foot[1], s.left_foot.y());
    EXPECT_EQ(p.right_foot[0], s.right_foot.x());
    // The first listed swing is the earliest that has not landed at t.
    int j = 0;
    while (j < feet.swings() && feet.swing_end(j) <= t) ++j;
    const int ahead = std::min(kWalkPlanSteps, feet.swings() - j);
    ASSERT_EQ(p.steps, ahead) << "t=" << t;
    for (int i = 0; i < ahead; ++i, ++j) {
      const Foot f = walking::Footsteps::swing_foot(j);
      EXPECT_EQ(p.step_foot[i], f == Foot::kLeft ? 1 : 2);
      EXPECT_DOUBLE_EQ(p.step_x[i], feet.foothold(j + 1)) << "t=" << t << " step " << i;
      EXPECT_EQ(p.step_y[i],
                f == Foot::kLeft ? pattern.parameters().d_0 : -pattern.parameters().d_0);
      if (i) EXPECT_NE(p.step_foot[i], p.step_foot[i - 1]);
      if (i) EXPECT_GE(p.step_x[i], p.step_x[i - 1]);
    }
  }
  // Mid-walk the plan reaches ahead of both feet.
  const double mid = 20 * T_step;
  const WalkPlan p = walking::walk_plan(pattern.sample(mid), feet, mid);
  EXPECT_EQ(p.steps, kWalkPlanSteps);
  EXPECT_GT(p.step_x[kWalkPlanSteps - 1], std::max(p.left_foot[0], p.right_foot[0]) + 0.05);
  // After the last landing nothing is planned.
  EXPECT_EQ(walking::walk_plan(pattern.sample(pattern.duration()), feet, pattern.duration()).steps,
            0);
}
// A re-planned walk (push recovery's step adjustment) lists its landings where the moved steps now
// are: the moved swing's landing by the step, the later ones by the walk's offset, and the feet of
// the plan are the adjusted pattern's.
TEST(WalkPlan, AMovedStepIsPlannedWhereItNowLands) {
  walking::AdjustedPattern pattern(walking::preset("medium"));
  const walking::Footsteps& feet = pattern.base().footsteps();
  const int j = 6;
  const double now = feet.swing_start(j) + 0.02;
  const WalkPlan before = walking::walk_plan(pattern.sample(now), pattern, now);
  const WalkPlan original = walking::walk_plan(pattern.base().sample(now), feet, now);
  for (int i = 0; i < kWalkPlanSteps; ++i) {  // unchanged: the same plan as the pattern's own
    EXPECT_EQ(before.step_x[i], original.step_x[i]);
    EXPECT_EQ(before.step_y[i], original.step_y[i]);
  }
  const Eigen::Vector2d step(0.04, 0.02);
  ASSERT_TRUE(pattern.adjust_step(now, step, 0.06).has_value());
  const walking::PatternSample s = pattern.sample(now);
  const WalkPlan p = walking::walk_plan(s, pattern, now);
  ASSERT_EQ(p.steps, kWalkPlanSteps);
  EXPECT_EQ(p.left_foot[0], s.left_foot.x());
  EXPECT_EQ(p.right_foot[1], s.right_foot.y());
  // Swing j is the first listed: it lands moved by the step; the next (the other foot) follows
  // with the whole walk's offset, as every later landing does.
  for (int i = 0; i < kWalkPlanSteps; ++i) {
    EXPECT_EQ(p.step_foot[i], original.step_foot[i]);
    EXPECT_NEAR(p.step_x[i] - original.step_x[i], step.x(), 1e-12) << "step " << i;
    EXPECT_NEAR(p.step_y[i] - original.step_y[i], step.y(), 1e-12) << "step " << i;
  }
}

}  // namespace
}  // namespace stride
