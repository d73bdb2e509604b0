// Pattern feet -> leg joint angles (Sec. 3.6) and the knee angles of Fig. 3.17.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::walking {
namespace {

TEST(LegPoints, StretchedLegHangsStraightBelowTheHip) {
  const LegPoints l = leg_points(model::Side::Left, model::LegAngles{}, {0, 0, 0});
  EXPECT_NEAR((l.hip - Eigen::Vector3d(0, 0.05, -0.085)).norm(), 0, 1e-12);
  EXPECT_NEAR((l.knee - Eigen::Vector3d(0, 0.05, -0.185)).norm(), 0, 1e-12);
  EXPECT_NEAR((l.ankle - Eigen::Vector3d(0, 0.05, -0.2879)).norm(), 0, 1e-12);
}

// Law of cosines: knee bend for a hip-ankle distance d (0 when stretched).
double knee_for_distance(double d) {
  const double l1 = nao::kThighLength, l2 = nao::kTibiaLength;
  return std::acos(std::clamp((l1 * l1 + l2 * l2 - d * d) / (2 * l1 * l2), -1.0, 1.0)) * -1.0 +
         std::acos(-1.0);
}

double support_knee(const PatternSample& s, const LegJoints& q) {
  return s.support == SupportPhase::kLeft ? q.left[3] : q.right[3];
}

TEST(LegJoints, IkReproducesTheFeetRelativeToTheWaist) {
  const StretchedKneePattern w(preset("medium"));
  for (double t = 0.0; t <= w.duration(); t += 0.37) {
    const PatternSample s = w.sample(t);
    const LegJoints q = leg_joints(s);
    ASSERT_TRUE(q.reachable) << "t = " << t;
    const Eigen::Vector3d up(0, 0, nao::kFootHeight);
    EXPECT_NEAR((leg_points(model::Side::Left, q.left, s.waist).ankle - s.left_foot - up).norm(),
                0.0, 1e-9)
        << "t = " << t;
    EXPECT_NEAR((leg_points(model::Side::Right, q.right, s.waist).ankle - s.right_foot - up).norm(),
                0.0, 1e-9)
        << "t = " << t;
  }
}

// Fig. 3.17: the support knee nearly stretches at mid single support.
TEST(LegJoints, SupportKneeAtMidSupportMatchesTheHipAnkleDistance) {
  for (const char* name : {"slow", "medium", "fast", "fig3.14"}) {
    const StretchedKneePattern w(preset(name));
    const PatternParameters& p = w.parameters();
    for (int j = p.development_steps() + 1; j < p.steps - p.decay_steps(); ++j) {
      const PatternSample s = w.sample(j * p.T_step());
      const LegJoints q = leg_joints(s);
      const model::Side side =
          s.support == SupportPhase::kLeft ? model::Side::Left : model::Side::Right;
      const LegPoints leg = leg_points(side, side == model::Side::Left ? q.left : q.right, s.waist);
      EXPECT_NEAR(support_knee(s, q), knee_for_distance((leg.ankle - leg.hip).norm()), 1e-9)
          << name << " j = " << j;
    }
  }
}

TEST(LegJoints, StretchedKneePatternStretchesConventionalStaysBent) {
  const PatternParameters p = preset("fig3.14");  // z_max = 0.331 m, nearly the stretched leg
  const auto stretched = sample_walk(StretchedKneePattern(p), 0.01);
  const auto conventional = sample_walk(ConventionalPattern(p), 0.01);
  double min_stretched = 10, min_conventional = 10;
  for (const PatternSample& s : stretched)
    if (s.support != SupportPhase::kDouble)
      min_stretched = std::min(min_stretched, support_knee(s, leg_joints(s)));
  for (const PatternSample& s : conventional) {
    const LegJoints q = leg_joints(s);
    min_conventional = std::min({min_conventional, q.left[3], q.right[3]});
  }
  EXPECT_LT(min_stretched, 0.25);
  EXPECT_GT(min_conventional, 0.6);  // z = 0.318 m (Table 4.5)
}

}  // namespace
}  // namespace stride::walking
