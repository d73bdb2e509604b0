// Hip strategy with the bang-bang torque (Eqs. 7.21-7.30, Algorithm 2, Fig. 7.9).
#include "behaviours/balance/hip_strategy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "behaviours/balance/lipm_solution.hpp"

namespace stride::balance {
namespace {

// RK4 of [x, xdot, theta, thetadot] with the breakpoints t1, t2 on step boundaries.
HipModelState integrate_bang_bang(const BalanceParams& p, const ComState& s0,
                                  const BangBangPlan& plan, double t_end) {
  const double w2 = p.omega() * p.omega();
  OdeState<4> y{s0.x, s0.v, p.theta0, p.theta_dot0};
  const double edges[] = {0.0, std::min(plan.profile.t1, t_end), std::min(plan.profile.t2, t_end),
                          t_end};
  for (int seg = 0; seg < 3; ++seg) {
    const double a = edges[seg], b = edges[seg + 1];
    if (b <= a) continue;
    const double tau = bang_bang_torque(plan.profile, 0.5 * (a + b));  // constant on the segment
    const std::function<OdeState<4>(double, const OdeState<4>&)> rhs =
        [&](double, const OdeState<4>& s) {  // Eqs. 7.22 (+ ankle ZMP) and tau = I thetaddot
          return OdeState<4>{s[1], w2 * (s[0] - plan.zmp) - tau / (p.mass * p.z_cm), s[3],
                             tau / p.inertia};
        };
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / 1e-4)));
    const double h = (b - a) / n;
    for (int i = 0; i < n; ++i) y = rk4_step<4>(rhs, a + i * h, y, h);
  }
  return {y[0], y[1], y[2], y[3], 0.0};
}

TEST(HipStrategy, BangBangTorqueProfile) {
  const BangBang b{16, 0.1, 0.25};
  EXPECT_DOUBLE_EQ(bang_bang_torque(b, 0.05), 16);
  EXPECT_DOUBLE_EQ(bang_bang_torque(b, 0.1), -16);
  EXPECT_DOUBLE_EQ(bang_bang_torque(b, 0.2), -16);
  EXPECT_DOUBLE_EQ(bang_bang_torque(b, 0.25), 0);
  EXPECT_DOUBLE_EQ(bang_bang_torque(b, -0.01), 0);
}

TEST(HipStrategy, Fig79LimitProfilesStopTheHatAtTheRomLimit) {
  const BalanceParams p;  // I = 0.1, tau = +-16, theta_max = 1.772308 / -0.485624, theta0 = 0
  const HipBoundaries h = hip_boundaries(p);
  // theta0 = thetadot0 = 0: t1 = sqrt(I theta_max / tau), t2 = 2 t1.
  EXPECT_NEAR(h.forward_profile.t1, std::sqrt(0.1 * 1.772308 / 16), 1e-12);
  EXPECT_NEAR(h.forward_profile.t2, 2 * h.forward_profile.t1, 1e-12);
  EXPECT_NEAR(h.backward_profile.t1, std::sqrt(0.1 * 0.485624 / 16), 1e-12);
  EXPECT_NEAR(h.forward_profile.t1, 0.105247, 1e-6);
  EXPECT_NEAR(h.backward_profile.t1, 0.055092, 1e-6);
  // Eq. 7.30 with m = 5.183 kg, z = 0.32 m.
  const double w = p.omega(), mg = p.mass * p.g;
  EXPECT_NEAR(h.forward, 16 / mg * std::pow(1 - std::exp(-w * h.forward_profile.t1), 2), 1e-12);
  EXPECT_NEAR(h.forward, 0.061374, 1e-6);
  EXPECT_NEAR(h.backward, -0.021750, 1e-6);
  // The HAT ends at rest exactly at the ROM limit.
  BangBangPlan plan;
  plan.profile = h.forward_profile;
  const HipModelState end = bang_bang_state(p, {}, plan, h.forward_profile.t2);
  EXPECT_NEAR(end.theta, 1.772308, 1e-12);
  EXPECT_NEAR(end.theta_dot, 0.0, 1e-12);
}

TEST(HipStrategy, Fig79InitialStates) {
  const BalanceParams p;
  for (const ComState s : {ComState{-0.1, 0.7}, ComState{0.1, -0.6}}) {
    const BangBangPlan plan = plan_hip(p, s);
    EXPECT_TRUE(plan.recoverable) << s.x << ", " << s.v;
    // Comes to rest over the ankle (the unstable mode amplifies rounding as e^{omega t}).
    const HipModelState late = bang_bang_state(p, s, plan, 3.0);
    EXPECT_NEAR(late.x, 0.0, 1e-6);
    EXPECT_NEAR(late.v, 0.0, 1e-5);
    EXPECT_LE(std::abs(plan.theta_peak), 1.772308);
    EXPECT_GE(plan.theta_peak, -0.485624);
  }
  // Switching times of the two recoverable starts: Algorithm 2, lines 4 and 7.
  const double w = p.omega(), mg = p.mass * p.g;
  auto t1_closed_form = [&](double xi, double tau) {
    return -std::log(1 - std::sqrt(mg / tau * xi)) / w;
  };
  EXPECT_NEAR(plan_hip(p, {-0.1, 0.7}).profile.t1, t1_closed_form(-0.1 + 0.7 / w, 16), 1e-12);
  EXPECT_NEAR(plan_hip(p, {0.1, -0.6}).profile.t1, t1_closed_form(0.1 - 0.6 / w, -16), 1e-12);
  EXPECT_DOUBLE_EQ(plan_hip(p, {0.1, -0.6}).profile.tau, -16);
  for (const ComState s : {ComState{0.0, -0.55}, ComState{0.0, 0.8}}) {
    const BangBangPlan plan = plan_hip(p, s);
    EXPECT_FALSE(plan.recoverable) << s.x << ", " << s.v;
    EXPECT_GT(std::abs(bang_bang_state(p, s, plan, 3.0).x), 1.0);  // falls
  }
}

TEST(HipStrategy, ClosedFormMatchesRk4) {
  BalanceParams p;
  for (const ComState s : {ComState{-0.1, 0.7}, ComState{0.1, -0.6}, ComState{0.0, 0.8}}) {
    const BangBangPlan plan = plan_hip(p, s);
    for (const double t : {0.05, plan.profile.t2, 1.0}) {
      const HipModelState exact = bang_bang_state(p, s, plan, t);
      const HipModelState numeric = integrate_bang_bang(p, s, plan, t);
      EXPECT_NEAR(exact.x, numeric.x, 1e-8 * std::max(1.0, std::abs(exact.x)));
      EXPECT_NEAR(exact.v, numeric.v, 1e-8 * std::max(1.0, std::abs(exact.v)));
      EXPECT_NEAR(exact.theta, numeric.theta, 1e-9);
      EXPECT_NEAR(exact.theta_dot, numeric.theta_dot, 1e-9);
    }
  }
}

TEST(HipStrategy, SwitchingTimesRoundTripWithInitialHatRate) {
  // Eq. 7.28 and the t1 formula after it invert Eq. 7.25, also with thetadot0 != 0.
  BalanceParams p;
  p.theta_dot0 = 0.8;
  for (const double shift : {0.01, 0.03, 0.05}) {
    const auto b = bang_bang_for_shift(p, p.tau_forward, shift);
    ASSERT_TRUE(b.has_value()) << shift;
    EXPECT_NEAR(hip_capture_shift(p, *b), shift, 1e-12);
    EXPECT_NEAR(b->t2, 2 * b->t1 + p.inertia * p.theta_dot0 / p.tau_forward, 1e-12);
    BangBangPlan plan;
    plan.profile = *b;
    EXPECT_NEAR(bang_bang_state(p, {}, plan, b->t2).theta_dot, 0.0, 1e-12);  // HAT at rest
  }
  // A shift beyond tau / (m g) can never be produced.
  EXPECT_FALSE(bang_bang_for_shift(p, p.tau_forward, 0.4).has_value());
}

}  // namespace
}  // namespace stride::balance
