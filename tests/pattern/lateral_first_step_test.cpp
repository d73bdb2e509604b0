// The first lateral step (Fig. 3.10: A_l = 0.035 m, T_stride = 0.88 s) and the mirrored last one.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "behaviours/walking/pattern/lateral_motion.hpp"

namespace stride::walking {
namespace {

constexpr double kPi = std::numbers::pi;

PatternParameters fig3_10() {
  PatternParameters p;
  p.A_l = 0.035;
  p.T_stride = 0.88;
  return p;
}

TEST(FirstStepCubic, MeetsTheBoundaryConditionsOfEq3_8) {
  const PatternParameters p = fig3_10();
  const double T = p.T_step(), w = p.omega();
  const FirstStepCubic c = first_step_cubic(p.A_l, w, T);
  EXPECT_EQ(c.at(0).p, 0.0);
  EXPECT_NEAR(c.at(T).p, 0.035, 1e-15);
  EXPECT_NEAR(c.at(T).v, 0.0, 1e-14);
  EXPECT_NEAR(c.at(T).a, -w * w * 0.035, 1e-12);
}

TEST(FirstStepCubic, MatchesTheClosedFormForOmegaTStepEqualPi) {
  // Eliminating Eq. 3.8 by hand with omega T_step = pi:
  // a3 = A_l (1 - pi^2/2) / T^3, a2 = A_l (pi^2 - 3) / T^2, a1 = A_l (3 - pi^2/2) / T.
  const PatternParameters p = fig3_10();
  const double T = 0.44, A = 0.035;
  const FirstStepCubic c = first_step_cubic(A, p.omega(), T);
  EXPECT_NEAR(c.a[3], A * (1 - kPi * kPi / 2) / (T * T * T), 1e-12);
  EXPECT_NEAR(c.a[2], A * (kPi * kPi - 3) / (T * T), 1e-12);
  EXPECT_NEAR(c.a[1], A * (3 - kPi * kPi / 2) / T, 1e-12);
  // The waist first leans right (negative y, over the right support foot), as in Fig. 3.10.
  EXPECT_LT(c.a[1], 0.0);
  // Lowest point where a1 + 2 a2 t + 3 a3 t^2 = 0 (the smaller root), then it rises to A_l.
  const double disc = std::sqrt(c.a[2] * c.a[2] - 3 * c.a[3] * c.a[1]);
  const double t_min = (-c.a[2] + disc) / (3 * c.a[3]);
  EXPECT_GT(t_min, 0.0);
  EXPECT_LT(t_min, T);
  EXPECT_NEAR(c.at(t_min).v, 0.0, 1e-12);
  EXPECT_LT(c.at(t_min).p, -0.004);  // about 5 mm to the right for the Fig. 3.10 parameters
  EXPECT_GT(c.at(t_min).p, -0.006);
}

TEST(LateralMotion, CosineAfterTheFirstStepAndMirroredLastStep) {
  PatternParameters p = fig3_10();
  p.steps = 7;  // odd: the cosine arrives at the last step on the right side
  const LateralMotion y(p);
  const double T = p.T_step();
  EXPECT_NEAR(y.at(T).p, p.A_l, 1e-15);
  EXPECT_NEAR(y.at(2 * T).p, -p.A_l, 1e-15);  // Eq. 3.9: one sway per stride
  EXPECT_NEAR(y.at(2.5 * T).p, p.A_l * std::cos(p.omega() * 1.5 * T), 1e-15);
  EXPECT_NEAR(y.at(6 * T).p, -p.A_l, 1e-15);
  // The last step is the first one mirrored in time and side; it ends between the feet.
  const FirstStepCubic c = first_step_cubic(p.A_l, p.omega(), T);
  for (double s : {0.05, 0.2, 0.4}) {
    EXPECT_NEAR(y.at(7 * T - s).p, -c.at(s).p, 1e-15);
    EXPECT_NEAR(y.at(7 * T - s).v, c.at(s).v, 1e-15);
  }
  EXPECT_EQ(y.at(7 * T).p, 0.0);
}

}  // namespace
}  // namespace stride::walking
