// Landing control through joint positions: the admittance filter against the closed-form step
// response of Eq. 6.13's mass-spring-damper (and its first-order and spring-only limits), the
// landing window's stages, and the sole offset the leg angles carry out.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "behaviours/landing/admittance.hpp"
#include "behaviours/landing/landing_control.hpp"
#include "behaviours/landing/landing_window.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"
#include "simulator/landing_metrics.hpp"
#include "tests/error_text.hpp"

namespace stride::behaviours {
namespace {

// Underdamped M e'' + B e' + K e = f from rest under a constant f (textbook closed form).
double underdamped_step(double m, double b, double k, double f, double t) {
  const double wn = std::sqrt(k / m), zeta = b / (2 * std::sqrt(k * m));
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  const double decay = std::exp(-zeta * wn * t);
  return f / k *
         (1 - decay * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t)));
}

TEST(Admittance, StepResponseIsTheMassSpringDamperClosedForm) {
  const Admittance a{1.5, 40, 3000};  // zeta 0.30, wn 44.7 rad/s
  const AdmittanceFilter filter(a, 0.01);
  AdmittanceState s;
  double peak = 0;
  for (int k = 1; k <= 40; ++k) {
    s = filter.step(s, 30);
    EXPECT_NEAR(s.offset, underdamped_step(1.5, 40, 3000, 30, 0.01 * k), 1e-9) << "frame " << k;
    peak = std::max(peak, s.offset);
  }
  // The peak overshoots the 10 mm static offset by exp(-pi zeta / sqrt(1 - zeta^2)) = 37.5 %;
  // the frames at 70 and 80 ms straddle the continuous peak at 73.6 ms.
  const double zeta = 40 / (2 * std::sqrt(3000 * 1.5));
  const double overshoot = std::exp(-std::numbers::pi * zeta / std::sqrt(1 - zeta * zeta));
  EXPECT_NEAR(static_offset(a, 30), 0.01, 1e-15);
  EXPECT_NEAR(overshoot, 0.375, 1e-3);
  EXPECT_LE(peak, 0.01 * (1 + overshoot));
  EXPECT_GT(peak, 0.01 * (1 + 0.98 * overshoot));
}

TEST(Admittance, WithoutMassItIsFirstOrderAndWithoutDampingASpring) {
  const AdmittanceFilter first({0, 60, 3000}, 0.01);  // time constant B / K = 20 ms
  AdmittanceState s;
  for (int k = 1; k <= 5; ++k) {
    const AdmittanceState next = first.step(s, 30);
    EXPECT_NEAR(next.offset, 0.01 * (1 - std::exp(-0.01 * k / 0.02)), 1e-12);
    EXPECT_NEAR(next.rate, (next.offset - s.offset) / 0.01, 1e-12);
    s = next;
  }
  EXPECT_NEAR(AdmittanceFilter({0, 0, 3000}, 0.01).step({}, 30).offset, 0.01, 1e-15);
}

TEST(Admittance, MeaninglessModelsAreOneLineNamingTheField) {
  using test_support::error_of;
  EXPECT_EQ(error_of([] {
              AdmittanceFilter({-1, 1, 1}, 0.01);
            }),
            "admittance mass: expected a number >= 0");
  EXPECT_EQ(error_of([] {
              AdmittanceFilter({0, 1, 0}, 0.01);
            }),
            "admittance stiffness: expected a number > 0");
  EXPECT_EQ(error_of([] {
              AdmittanceFilter({0, 1, 1}, 0);
            }),
            "admittance period: expected a time > 0");
}

TEST(LandingWindow, SwingThenLandOnTheFirstLoadThenHandBackSmoothly) {
  const LandingWindow w;  // lift 4 mm, touch 0.5 mm, 5 N, hold 0.12 s, return 0.10 s
  FootLanding f;
  f = advance_landing(f, w, 0.00, 0.010, 0);
  EXPECT_EQ(f.stage, LandingStage::swinging);
  f = advance_landing(f, w, 0.01, 0.008, 1);  // on the way down, no load yet
  EXPECT_EQ(f.stage, LandingStage::swinging);
  f = advance_landing(f, w, 0.02, 0.003, 8);  // first load above 5 N: touched down early
  EXPECT_EQ(f.stage, LandingStage::landing);
  EXPECT_EQ(f.weight, 1);
  f = advance_landing(f, w, 0.13, 0.0, 40);
  EXPECT_EQ(f.stage, LandingStage::landing);
  f = advance_landing(f, w, 0.14, 0.0, 40);  // hold of 0.12 s over: the return begins
  EXPECT_EQ(f.stage, LandingStage::returning);
  EXPECT_EQ(f.weight, 1);
  f = advance_landing(f, w, 0.19, 0.0, 40);
  EXPECT_NEAR(f.weight, 0.5, 1e-12);  // halfway through a symmetric ramp
  f = advance_landing(f, w, 0.25, 0.0, 40);
  EXPECT_EQ(f.stage, LandingStage::idle);
  EXPECT_EQ(f.weight, 0);
}

TEST(LandingWindow, ALoadWhileThePlanLiftsTheFootIsNotATouchDown) {
  FootLanding f;
  f = advance_landing(f, {}, 0.00, 0.005, 30);
  f = advance_landing(f, {}, 0.01, 0.009, 30);  // rising, the sole still peeling off
  EXPECT_EQ(f.stage, LandingStage::swinging);
}

TEST(SoleOffset, RaisesTheSoleStraightUpAndTurnsTheAnkle) {
  Eigen::Isometry3d sole = Eigen::Isometry3d::Identity();
  sole.translation() << 0.01, 0.05, -0.31;
  const model::LegAngles q = model::leg_ik(model::Side::Left, sole).q;
  const model::LegAngles raised = offset_sole(model::Side::Left, q, 0.012, 0, 0);
  const Eigen::Isometry3d after = model::leg_fk(model::Side::Left, raised);
  EXPECT_NEAR((after.translation() - sole.translation() - Eigen::Vector3d(0, 0, 0.012)).norm(), 0,
              1e-9);
  EXPECT_NEAR((after.linear() - sole.linear()).norm(), 0, 1e-9);
  EXPECT_EQ(raised[0], q[0]);  // HipYawPitch is shared with the other leg
  const model::LegAngles tilted = offset_sole(model::Side::Left, q, 0, 0.05, -0.02);
  EXPECT_NEAR(tilted[4] - q[4], 0.05, 1e-15);
  EXPECT_NEAR(tilted[5] - q[5], -0.02, 1e-15);
}

TEST(SoleOffset, MomentsOfALoadAheadAndLeftOfTheReference) {
  // 20 N at 5 cm ahead and 2 cm left: toes pressed up (pitch moment < 0), left edge up (> 0).
  const Eigen::Vector2d m = sole_moments(20, {0.06, 0.02}, {0.01, 0});
  EXPECT_NEAR(m.x(), -1.0, 1e-12);
  EXPECT_NEAR(m.y(), 0.4, 1e-12);
}

TEST(LandingMetrics, TheSummaryKeepsTheTouchDownsFromTheWalksStart) {
  // The first contact (the robot set on the floor) is before the walk and left out.
  const std::vector<sim::Touchdown> t = {{0, 0.05, 0.9, 300, 100, false},
                                         {0, 2.50, 0.2, 80, 70, false},
                                         {1, 3.00, 0.4, 100, 90, true}};
  const sim::LandingMetricsResult r = sim::summarize_touchdowns(t, 2.0);
  EXPECT_EQ(r.touchdowns, 2);
  EXPECT_NEAR(r.mean_impulse, 0.3, 1e-15);
  EXPECT_NEAR(r.mean_peak_force, 90, 1e-12);
  EXPECT_EQ(r.max_peak_force, 100);
  EXPECT_EQ(r.max_peak_fsr, 90);
  EXPECT_EQ(r.rebounds, 1);
  EXPECT_EQ(sim::summarize_touchdowns(t, 0).max_peak_force, 300);
}

}  // namespace
}  // namespace stride::behaviours
