// Phase joins of the walking pattern: position, velocity and acceleration continuous (Ch. 3).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "behaviours/walking/pattern/forward_motion.hpp"
#include "behaviours/walking/pattern/lateral_motion.hpp"
#include "behaviours/walking/pattern/vertical_motion.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"

namespace stride::walking {
namespace {

constexpr double kEps = 1e-11;  // one-sided limits; jumps would be far above 1e-9
constexpr double kTol = 1e-9;

void expect_continuous(const Motion1d& left, const Motion1d& right, const std::string& where) {
  EXPECT_NEAR(left.p, right.p, kTol) << where << " position";
  EXPECT_NEAR(left.v, right.v, kTol) << where << " velocity";
  EXPECT_NEAR(left.a, right.a, kTol) << where << " acceleration";
}

class Continuity : public testing::TestWithParam<const char*> {};

TEST_P(Continuity, ForwardAndLateralAreC2AtEveryStepAndDoubleSupportJoin) {
  const PatternParameters p = preset(GetParam());
  const ForwardMotion x(p);
  const LateralMotion y(p);
  for (int j = 0; j <= p.steps; ++j) {
    for (double offset : {0.0, p.T_s(), p.T_d()}) {
      const double t = j * p.T_step() + offset;
      if (t >= p.steps * p.T_step() && offset > 0) continue;
      const std::string where = "t = " + std::to_string(t);
      expect_continuous(x.at(t - kEps), x.at(t + kEps), "x at " + where);
      // Eq. 3.8 leaves the first step's initial lateral velocity free: only inner joins.
      if (t > 0 && t < p.steps * p.T_step())
        expect_continuous(y.at(t - kEps), y.at(t + kEps), "y at " + where);
    }
  }
}

TEST_P(Continuity, WaistHeightIsC2AtStepJoinsAndC1AtDoubleSupportJoins) {
  const PatternParameters p = preset(GetParam());
  for (int j = 1; j < p.steps; ++j) {
    const double t = j * p.T_step();
    expect_continuous(waist_height(p, t - kEps), waist_height(p, t + kEps), "z at step join");
  }
  // Eq. 3.10 meets the constant z_min with zero slope but curvature A_s (pi / T_s)^2.
  const double jump = 0.5 * (p.z_max - p.z_min) * std::pow(std::numbers::pi / p.T_s(), 2);
  for (int j = 0; j < p.steps; ++j) {
    for (double offset : {p.T_s(), p.T_d()}) {
      const double t = j * p.T_step() + offset;
      const Motion1d a = waist_height(p, t - kEps), b = waist_height(p, t + kEps);
      EXPECT_NEAR(a.p, b.p, kTol);
      EXPECT_NEAR(a.v, b.v, kTol);
      EXPECT_NEAR(std::abs(a.a - b.a), jump, 1e-6);
    }
  }
}

TEST_P(Continuity, FeetMoveContinuouslyAndRestOnTheGroundOutsideTheirSwing) {
  const StretchedKneePattern pattern(preset(GetParam()));
  const double dt = 1e-4;
  PatternSample prev = pattern.sample(0.0);
  for (double t = dt; t <= pattern.duration(); t += dt) {
    const PatternSample s = pattern.sample(t);
    EXPECT_LT((s.left_foot - prev.left_foot).norm(), 1e-3) << "left foot jumps at t = " << t;
    EXPECT_LT((s.right_foot - prev.right_foot).norm(), 1e-3) << "right foot jumps at t = " << t;
    if (s.support == SupportPhase::kLeft || s.support == SupportPhase::kDouble) {
      EXPECT_EQ(s.left_foot.z(), 0.0) << t;
    }
    if (s.support == SupportPhase::kRight || s.support == SupportPhase::kDouble) {
      EXPECT_EQ(s.right_foot.z(), 0.0) << t;
    }
    prev = s;
  }
  EXPECT_NEAR(prev.left_foot.x(), prev.right_foot.x(), 1e-12) << "feet side by side at the end";
}

INSTANTIATE_TEST_SUITE_P(Presets, Continuity,
                         testing::Values("slow", "medium", "fast", "fig3.14", "fig3.16"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (c == '.') c = '_';
                           return n;
                         });

TEST(DevelopmentQuartic, MeetsTheBoundaryConditionsOfEq3_6) {
  const PatternParameters p = preset("fig3.14");
  const SpeedLevel level2 = p.development[0];  // V_min2, V_max2
  const double T = p.T_step(), T_s = p.T_s();
  const VelocityQuartic q = development_quartic(0.0, level2.V_min, rhythmic_jerk(level2, T_s), T);
  EXPECT_NEAR(q.at(0).v, 0.0, 1e-15);
  EXPECT_NEAR(q.at(T).v, level2.V_min, 1e-12);
  EXPECT_NEAR(q.at(0).a, 0.0, 1e-15);
  EXPECT_NEAR(q.at(T).a, 0.0, 1e-12);
  const double A_m_prime = std::numbers::pi * (level2.V_max - level2.V_min) / (2 * T_s);
  EXPECT_NEAR(q.jerk(T), A_m_prime * std::numbers::pi / T_s, 1e-9);
  // ... and the next rhythmic step at that level starts with that second derivative.
  const double du = 1e-6;
  const double jerk_rhythmic = (rhythmic_step(level2, T_s, p.T_d(), du).a) / du;
  EXPECT_NEAR(jerk_rhythmic, q.jerk(T), 1e-4);
}

TEST(RhythmicStep, PositionIsTheIntegralOfTheVelocityOfEq3_1) {
  const SpeedLevel level{0.18, 0.19};
  const double T_s = 0.12375, T_d = 0.12625, T = T_s + T_d;
  double integral = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) integral += rhythmic_step(level, T_s, T_d, (i + 0.5) * T / n).v;
  integral *= T / n;
  EXPECT_NEAR(rhythmic_step(level, T_s, T_d, T).p, integral, 1e-9);
  // One step covers V_max T_d + V_min T_s = pi alpha (Eq. 3.14).
  EXPECT_NEAR(rhythmic_step(level, T_s, T_d, T).p, level.V_max * T_d + level.V_min * T_s, 1e-12);
}

}  // namespace
}  // namespace stride::walking
