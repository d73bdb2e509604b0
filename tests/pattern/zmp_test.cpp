// ZMP of the point-mass pattern (Eq. 3.16) against closed forms and the NAO support polygon.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "behaviours/walking/pattern/point_mass_zmp.hpp"
#include "behaviours/walking/pattern/support_polygon.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::walking {
namespace {

// Eq. 3.16 at the middle of a rhythmic single support: y = +-A_l, y'' = -omega^2 y, x'' = 0,
// z = z_max, z'' = -A_s (pi / T_s)^2.
double mid_support_zmp_y(const PatternParameters& p) {
  const double A_s = 0.5 * (p.z_max - p.z_min), k = std::numbers::pi / p.T_s();
  return p.A_l * (1.0 + p.omega() * p.omega() * p.z_max / (p.gravity - A_s * k * k));
}

TEST(PointMassZmp, StandingMassHasItsZmpBelowIt) {
  const Eigen::Vector2d z = point_mass_zmp({0.1, -0.2, 0.3}, Eigen::Vector3d::Zero(), 9.81);
  EXPECT_DOUBLE_EQ(z.x(), 0.1);
  EXPECT_DOUBLE_EQ(z.y(), -0.2);
  // A horizontal acceleration shifts it back by z a / g (the cart-table / LIPM relation).
  EXPECT_NEAR(point_mass_zmp({0, 0, 0.3}, {1.0, 0, 0}, 9.81).x(), -0.3 / 9.81, 1e-15);
}

TEST(PointMassZmp, MatchesTheClosedFormAtRhythmicBoundaries) {
  for (const char* name : {"medium", "fig3.16"}) {
    const StretchedKneePattern w(preset(name));
    const PatternParameters& p = w.parameters();
    for (int j = p.development_steps() + 1; j < p.steps - p.decay_steps(); ++j) {
      const PatternSample s = w.sample(j * p.T_step());
      const double side = (j % 2 == 1) ? 1.0 : -1.0;  // over the left foot at odd j
      EXPECT_NEAR(s.zmp.y(), side * mid_support_zmp_y(p), 1e-12) << name << " j = " << j;
      EXPECT_NEAR(s.zmp.x(), s.waist.x(), 1e-12) << name << " j = " << j;
    }
  }
}

TEST(SupportPolygon, SupportSoleInSingleSupportHullOfBothInDoubleSupport) {
  PatternSample s;
  s.left_foot = {0, 0.05, 0};
  s.right_foot = {0.05, -0.05, 0};
  s.zmp = {0.02, 0.0556};  // left sole centre: half the sole width from its long edges
  EXPECT_NEAR(zmp_margin(s), 0.0455, 1e-12);
  EXPECT_EQ(both_soles_polygon(s).size, 6);  // two corners of each sole hidden in the hull
  s.zmp = {0.03, 0.0};                       // between the feet
  EXPECT_GT(zmp_margin(s), 0.0);
  s.support = SupportPhase::kLeft;
  EXPECT_NEAR(zmp_margin(s), -0.0101, 1e-12);  // the left sole's inner edge is at y = 0.0101
  s.support = SupportPhase::kRight;
  EXPECT_LT(zmp_margin(s), 0.0);
}

// Fig. 3.16's sway (A_l = 0.025 m, T_stride = 1.16 s) carries the ZMP onto the support sole.
TEST(ZmpInSupportPolygon, Fig3_16PatternKeepsTheZmpOnTheSoles) {
  const StretchedKneePattern w(preset("fig3.16"));
  const PatternParameters& p = w.parameters();
  EXPECT_NEAR(mid_support_zmp_y(p), p.d_0, 0.002);  // ZMP peaks under the ankle
  for (const PatternSample& s : sample_walk(w, 0.005)) {
    EXPECT_GE(model::stability_margin(s.zmp, both_soles_polygon(s)), 0.0) << "t = " << s.t;
    // The half-length first and last swings are excepted: there the cubic of Eq. 3.7 crosses
    // the walking line before the swing foot lands.
    if (s.t > p.T_s() && s.t < w.duration() - p.T_s()) {
      EXPECT_GE(zmp_margin(s), 0.0) << "t = " << s.t;
    }
  }
}

// Table 4.3's 1 mm (0.5 mm fast) sway keeps the point-mass ZMP between the soles: the robot's
// own lateral oscillation is relied on (Sec. 4.3.4.2), so only the double-support hull holds.
TEST(ZmpInSupportPolygon, Table4_3PatternsKeepTheZmpBetweenTheSoles) {
  for (const char* name : {"slow", "medium", "fast"}) {
    const StretchedKneePattern w(preset(name));
    const PatternParameters& p = w.parameters();
    const double inner_edge = p.d_0 - (0.5 * nao::kSoleWidth - nao::kSoleCentreYLeft);
    EXPECT_LT(mid_support_zmp_y(p), inner_edge) << name;
    for (const PatternSample& s : sample_walk(w, 0.005)) {
      EXPECT_GE(model::stability_margin(s.zmp, both_soles_polygon(s)), 0.0)
          << name << " t = " << s.t;
      EXPECT_LT(std::abs(s.zmp.y()), inner_edge) << name << " t = " << s.t;
    }
  }
}

// Why no reading of A_l or of the sole fixes that: with tau_dsp = 1 % the cosine sway (Eq. 3.9)
// crosses the walking line in the middle of the 2.5 ms double support, so every single support
// starts with the ZMP (Eq. 3.16) only about 0.09 A_l off the line. Reaching even a sole centred
// under the ankle (inner edge d_0 - 45.5 mm = 4.5 mm) there takes A_l >= 48 mm, whose
// mid-support ZMP (about 6.6 A_l) lies beyond the sole's outer edge (101 mm).
TEST(ZmpInSupportPolygon, Table4_3TimingAllowsNoSwayThatKeepsTheZmpOnTheSupportSole) {
  for (const char* name : {"slow", "medium", "fast"}) {
    const StretchedKneePattern w(preset(name));
    const PatternParameters& p = w.parameters();
    const double A_s = 0.5 * (p.z_max - p.z_min), k = std::numbers::pi / p.T_s();
    // Start of single support: z = z_min with z'' = A_s k^2 (Eq. 3.10), y from Eq. 3.9.
    const double start_per_A_l =
        std::abs(std::cos(std::numbers::pi * p.T_d() / p.T_step())) *
        (1.0 + p.omega() * p.omega() * p.z_min / (p.gravity + A_s * k * k));
    for (int j = p.development_steps() + 1; j < p.steps - p.decay_steps() - 1; ++j) {
      // 1 ns into the single support, on Eq. 3.10's rising branch (z'' jumps at T_d).
      const PatternSample s = w.sample(j * p.T_step() + p.T_d() + 1e-9);
      ASSERT_NE(s.support, SupportPhase::kDouble) << name << " j = " << j;
      EXPECT_NEAR(std::abs(s.zmp.y()), p.A_l * start_per_A_l, 1e-10) << name << " j = " << j;
      EXPECT_LT(zmp_margin(s), -0.009) << name << " j = " << j;  // the sole's edge is 10.1 mm off
    }
    const double centred_inner = p.d_0 - 0.5 * nao::kSoleWidth;  // 4.5 mm from the line
    const double outer = p.d_0 + 0.5 * nao::kSoleWidth + nao::kSoleCentreYLeft;  // 101.1 mm
    const double least_A_l = centred_inner / start_per_A_l;
    const double most_A_l = outer / (mid_support_zmp_y(p) / p.A_l);
    EXPECT_GT(start_per_A_l, 0.0) << name;
    EXPECT_LT(start_per_A_l, 0.11) << name;
    EXPECT_GT(least_A_l, most_A_l) << name << ": A_l from " << least_A_l << " to " << most_A_l;
  }
}

}  // namespace
}  // namespace stride::walking
