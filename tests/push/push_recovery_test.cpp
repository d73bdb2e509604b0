// Push recovery while walking: the capture point of a deviation, the response the Ch. 7
// boundaries name for it, the stepping response's clamped landing, and the re-planned pattern
// that puts the swing foot down there and carries the rest of the walk along.
#include <cmath>

#include <gtest/gtest.h>

#include "behaviours/balance/modules/com_state_estimator.hpp"
#include "behaviours/balance/strategy_classifier.hpp"
#include "behaviours/push_recovery/push_detector.hpp"
#include "behaviours/walking/pattern/adjusted_pattern.hpp"
#include "behaviours/walking/pattern/pattern_parameters.hpp"

namespace stride::behaviours {
namespace {

TEST(PushDetector, CapturePointIsDeviationPlusRateOverOmega) {
  // z = 0.26 m: omega = sqrt(9.81 / 0.26) = 6.1426 1/s.
  const Eigen::Vector2d xi = capture_deviation({0.01, -0.004}, {0.3, 0.1}, 9.81, 0.26);
  EXPECT_NEAR(xi.x(), 0.01 + 0.3 / std::sqrt(9.81 / 0.26), 1e-15);
  EXPECT_NEAR(xi.x(), 0.058840, 1e-6);
  EXPECT_NEAR(xi.y(), 0.012280, 1e-6);
}

TEST(PushDetector, TheSoleBeyondThePlannedZmpBoundsTheAnkle) {
  balance::BalanceParams robot;
  robot.z_cm = 0.26;
  // Sole from 3 cm behind to 7 cm ahead of the ankle, planned ZMP 2 cm ahead: +-5 cm left.
  const balance::BalanceParams p = deviation_model(robot, -0.03, 0.07, 0.02);
  EXPECT_NEAR(p.zmp_min, -0.05, 1e-15);
  EXPECT_NEAR(p.zmp_max, 0.05, 1e-15);
  const double w = p.omega();
  EXPECT_EQ(classify_deviation(p, {0.0, 0.019 * w}, 0.02, false), PushResponse::none);
  EXPECT_EQ(classify_deviation(p, {0.0, 0.049 * w}, 0.02, false), PushResponse::ankle);
  EXPECT_EQ(classify_deviation(p, {0.0, 0.051 * w}, 0.02, false), PushResponse::step);
  EXPECT_EQ(classify_deviation(p, {0.0, -0.051 * w}, 0.02, false), PushResponse::step);
  // With the hip allowed, just past the sole the trunk recovers it (Eq. 7.30's region is wider).
  const balance::Classification c = balance::classify(p, {0.0, 0.051 * w});
  EXPECT_FALSE(c.ankle_recovers);
  EXPECT_TRUE(c.hip_recovers);
  EXPECT_EQ(classify_deviation(p, {0.0, 0.051 * w}, 0.02, true), PushResponse::hip);
  // Past the hip boundary too: the combined strategy, then nothing but a step.
  EXPECT_EQ(classify_deviation(p, {0.0, (c.hip.hi + 0.002) * w}, 0.02, true),
            PushResponse::combined);
  EXPECT_EQ(classify_deviation(p, {0.0, (c.combined.hi + 0.002) * w}, 0.02, true),
            PushResponse::step);
  // A planned ZMP near the sole's front leaves the ankle room backward only.
  const balance::BalanceParams front = deviation_model(robot, -0.03, 0.07, 0.06);
  EXPECT_EQ(classify_deviation(front, {0.0, 0.03 * w}, 0.02, false), PushResponse::step);
  EXPECT_EQ(classify_deviation(front, {0.0, -0.03 * w}, 0.02, false), PushResponse::ankle);
}

TEST(PushDetector, TheCaptureStepIsClampedOutwardMoreThanInward) {
  const StepLimits lim;  // 4 cm forward, 3 back, 4 out, 1 in
  EXPECT_EQ(capture_step({0.02, 0.01}, 1.0, lim, true), Eigen::Vector2d(0.02, 0.01));
  EXPECT_EQ(capture_step({0.10, 0.10}, 1.0, lim, true), Eigen::Vector2d(0.04, 0.04));
  EXPECT_EQ(capture_step({-0.10, -0.10}, 1.0, lim, true), Eigen::Vector2d(-0.03, -0.01));
  // The right foot's outward is -y.
  EXPECT_EQ(capture_step({0.0, -0.10}, 1.0, lim, false), Eigen::Vector2d(0.0, -0.04));
  EXPECT_EQ(capture_step({0.0, 0.10}, 1.0, lim, false), Eigen::Vector2d(0.0, 0.01));
  EXPECT_EQ(capture_step({0.02, 0.0}, 1.5, lim, false), Eigen::Vector2d(0.03, 0.0));
}

TEST(PushDetector, TheAnkleActsOnTheCapturePointBeyondItsDeadBand) {
  // Pitch: (0.05 - 0.02) * 1.5 = 0.045 rad, toes down; roll: (0.10 - 0.08) * 1.5 = 0.03 rad on
  // the +y edge, a negative roll.
  const Eigen::Vector2d a = ankle_response({0.05, 0.10}, {0.02, 0.08}, {1.5, 1.5}, 0.12);
  EXPECT_NEAR(a.x(), 0.045, 1e-15);
  EXPECT_NEAR(a.y(), -0.03, 1e-15);
  // Within the dead band nothing; backward and to the right the signs turn.
  EXPECT_EQ(ankle_response({0.019, -0.079}, {0.02, 0.08}, {1.5, 1.5}, 0.12),
            Eigen::Vector2d(0.0, 0.0));
  const Eigen::Vector2d b = ankle_response({-0.06, -0.11}, {0.02, 0.08}, {1.5, 2.0}, 0.12);
  EXPECT_NEAR(b.x(), -0.06, 1e-15);
  EXPECT_NEAR(b.y(), 0.06, 1e-15);
  // Clamped to the largest offset.
  EXPECT_EQ(ankle_response({0.3, -0.3}, {0.02, 0.08}, {1.5, 1.5}, 0.12),
            Eigen::Vector2d(0.12, 0.12));
}

TEST(AdjustedPattern, TheMovedSwingFootLandsAtTheClampedCapturePoint) {
  walking::AdjustedPattern pattern(walking::preset("medium"));
  const walking::Footsteps& f = pattern.base().footsteps();
  const int j = 6;
  const double now = f.swing_start(j) + 0.02;
  const bool left = walking::Footsteps::swing_foot(j) == walking::Foot::kLeft;
  const Eigen::Vector2d step = capture_step({0.09, 0.02}, 1.0, {}, left);  // x clamped to 4 cm
  EXPECT_EQ(step, Eigen::Vector2d(0.04, left ? 0.02 : 0.01));
  const walking::PatternSample before = pattern.sample(now);
  const auto a = pattern.adjust_step(now, step, 0.06);
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->swing, j);
  EXPECT_EQ(a->landing, f.swing_end(j));
  // No jump where the change is made.
  const walking::PatternSample at = pattern.sample(now);
  EXPECT_NEAR((at.left_foot - before.left_foot).norm(), 0, 1e-12);
  EXPECT_NEAR((at.waist - before.waist).norm(), 0, 1e-12);
  // The landing moved by the step; the waist is over the moved walk by then.
  const auto foot = [&](const walking::PatternSample& s) {
    return left ? s.left_foot : s.right_foot;
  };
  const walking::PatternSample landed = pattern.sample(a->landing);
  const walking::PatternSample plan = pattern.base().sample(a->landing);
  EXPECT_NEAR((foot(landed) - foot(plan)).head<2>().x(), 0.04, 1e-12);
  EXPECT_NEAR((foot(landed) - foot(plan)).head<2>().y(), step.y(), 1e-12);
  EXPECT_NEAR((landed.waist - plan.waist).head<2>().x(), 0.04, 1e-12);
  // The other foot follows in its next swing: two swings on, the whole walk is moved.
  const double later = f.swing_end(j + 1) + 0.01;
  const walking::PatternSample moved = pattern.sample(later);
  const walking::PatternSample base = pattern.base().sample(later);
  EXPECT_NEAR((moved.left_foot - base.left_foot).head<2>().x(), 0.04, 1e-12);
  EXPECT_NEAR((moved.right_foot - base.right_foot).head<2>().x(), 0.04, 1e-12);
  EXPECT_EQ(pattern.total_offset(), step);
}

TEST(PushDetector, TheStanceSoleChangesOnlyPastTheHysteresis) {
  EXPECT_EQ(support_sole(GroundOrigin::between_feet, 26, 26, 5), GroundOrigin::left_sole);
  EXPECT_EQ(support_sole(GroundOrigin::left_sole, 20, 24, 5), GroundOrigin::left_sole);
  EXPECT_EQ(support_sole(GroundOrigin::left_sole, 20, 26, 5), GroundOrigin::right_sole);
  EXPECT_EQ(support_sole(GroundOrigin::right_sole, 24, 20, 5), GroundOrigin::right_sole);
}

}  // namespace
}  // namespace stride::behaviours
