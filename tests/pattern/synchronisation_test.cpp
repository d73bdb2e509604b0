// Simultaneous planning of waist and feet (Sec. 3.4-3.5, Eqs. 3.11-3.15).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "behaviours/walking/pattern/walking_pattern.hpp"

namespace stride::walking {
namespace {

const PatternSample at_boundary(const StretchedKneePattern& w, int j) {
  return w.sample(j * w.parameters().T_step());
}

class Synchronisation : public testing::TestWithParam<const char*> {};

TEST_P(Synchronisation, SupportFootIsUnderTheWaistAtEveryStepBoundary) {
  const StretchedKneePattern w(preset(GetParam()));
  for (int j = 0; j <= w.parameters().steps; ++j) {
    const PatternSample s = at_boundary(w, j);
    // Eq. 3.12: odd boundaries stand on the left foot, even ones on the right.
    const Eigen::Vector3d& support = (j % 2 == 1) ? s.left_foot : s.right_foot;
    EXPECT_NEAR(s.waist.x(), support.x(), 1e-9) << "j = " << j;
    EXPECT_EQ(support.z(), 0.0) << "j = " << j;
  }
}

TEST_P(Synchronisation, BothFeetMeetTheWaistAtRhythmicStepBoundaries) {
  const StretchedKneePattern w(preset(GetParam()));
  const PatternParameters& p = w.parameters();
  const int first = p.development_steps() + 1, last = p.development_steps() + p.rhythmic_steps();
  ASSERT_GT(last, first);
  for (int j = first; j < last; ++j) {
    const PatternSample s = at_boundary(w, j);  // Eq. 3.12, both feet
    EXPECT_NEAR(s.waist.x(), s.left_foot.x(), 1e-9) << "j = " << j;
    EXPECT_NEAR(s.waist.x(), s.right_foot.x(), 1e-9) << "j = " << j;
    // The swing foot is at its highest point, H_foot (delta alpha (1 - cos pi)).
    EXPECT_NEAR(std::max(s.left_foot.z(), s.right_foot.z()), p.H_foot, 1e-12) << "j = " << j;
  }
}

TEST_P(Synchronisation, RhythmicStepLengthIsPiAlpha) {
  const StretchedKneePattern w(preset(GetParam()));
  const PatternParameters& p = w.parameters();
  const double alpha = synchronisation_alpha(p.rhythmic, p.T_s(), p.T_d());  // Eq. 3.15
  const int j = p.development_steps() + 1;
  EXPECT_NEAR(w.footsteps().foothold(j + 1) - w.footsteps().foothold(j), std::numbers::pi * alpha,
              1e-12);
}

INSTANTIATE_TEST_SUITE_P(Presets, Synchronisation, testing::Values("slow", "medium", "fast"));

TEST(Cycloid, CoversTheDistanceAndPeaksAtHFootMidSwing) {
  const double L = 0.1, H = 0.026;
  EXPECT_NEAR(cycloid(L, H, 0.0).norm(), 0.0, 1e-15);
  EXPECT_NEAR(cycloid(L, H, 0.5).x(), 0.5 * L, 1e-15);
  EXPECT_NEAR(cycloid(L, H, 0.5).y(), H, 1e-15);
  EXPECT_NEAR(cycloid(L, H, 1.0).x(), L, 1e-15);
  EXPECT_NEAR(cycloid(L, H, 1.0).y(), 0.0, 1e-15);
  // Eq. 3.11 at psi = pi / 2 with alpha = L / (2 pi): x = alpha (pi / 2 - 1), z = H / 2.
  const double alpha = L / (2 * std::numbers::pi);
  EXPECT_NEAR(cycloid(L, H, 0.25).x(), alpha * (std::numbers::pi / 2 - 1), 1e-15);
  EXPECT_NEAR(cycloid(L, H, 0.25).y(), 0.5 * H, 1e-15);
}

TEST(SupportPhase, SingleSupportLastsTwoTsAroundEachBoundary) {
  const StretchedKneePattern w(preset("medium"));
  const PatternParameters& p = w.parameters();
  const double T = p.T_step(), T_s = p.T_s(), T_d = p.T_d();
  EXPECT_EQ(w.footsteps().support(0.5 * T_s), SupportPhase::kRight);  // first swing: left foot
  EXPECT_EQ(w.footsteps().support(0.5 * (T_s + T_d)), SupportPhase::kDouble);
  EXPECT_EQ(w.footsteps().support(T), SupportPhase::kLeft);
  EXPECT_EQ(w.footsteps().support(2 * T), SupportPhase::kRight);
  EXPECT_EQ(w.footsteps().support(2 * T + T_s + 1e-9), SupportPhase::kDouble);
  EXPECT_EQ(w.footsteps().support(p.steps * T + 0.1), SupportPhase::kDouble);
  EXPECT_EQ(w.footsteps().swings(), 61);  // Sec. 4.3.4.2: 61 steps in 15 s
  EXPECT_DOUBLE_EQ(w.duration(), 15.0);
}

TEST(Pattern, RestsBeforeAndAfterTheWalkForAnyTime) {
  const StretchedKneePattern w(preset("slow"));
  const PatternSample end = w.sample(w.duration());
  for (double t : {-1.0, 1e300, std::nan(""), -1e300}) {
    const PatternSample s = w.sample(t);
    const PatternSample& rest = (t > 0) ? end : w.sample(0.0);
    EXPECT_EQ(s.waist, rest.waist) << t;
    EXPECT_EQ(s.waist_velocity, Eigen::Vector3d::Zero()) << t;
    EXPECT_EQ(s.left_foot, rest.left_foot) << t;
    EXPECT_EQ(s.right_foot, rest.right_foot) << t;
    EXPECT_EQ(s.support, SupportPhase::kDouble) << t;
  }
  EXPECT_EQ(end.left_foot.x(), end.waist.x());  // back over both feet
  EXPECT_EQ(end.right_foot.x(), end.waist.x());
  EXPECT_EQ(end.waist.y(), 0.0);
}

}  // namespace
}  // namespace stride::walking
