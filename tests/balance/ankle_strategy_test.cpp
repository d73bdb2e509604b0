// Ankle strategy: Fig. 7.4 open-loop boundaries, Fig. 7.5-7.7 PD closed loop (Eqs. 7.5-7.20).
#include "behaviours/balance/ankle_strategy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "behaviours/balance/lipm_solution.hpp"
#include "robot/core/error.hpp"

namespace stride::balance {
namespace {

TEST(AnkleOpenLoop, Fig74BoundariesAreTheBorderCapturePoints) {
  const BalanceParams p;  // g = 9.81, z = 0.32, x_zmp in [-0.056, 0.103] as in Fig. 7.4
  const double w = std::sqrt(9.81 / 0.32);
  EXPECT_NEAR(p.omega(), 5.536809, 1e-6);
  const PhaseLine l1 = ankle_front_boundary(p), l2 = ankle_back_boundary(p);
  EXPECT_NEAR(l1.slope, -w, 1e-12);
  EXPECT_NEAR(l1.intercept, 0.103 * w, 1e-12);   // 0.570291 m/s at x = 0
  EXPECT_NEAR(l2.intercept, -0.056 * w, 1e-12);  // -0.310061 m/s at x = 0
  EXPECT_NEAR(l1.intercept, 0.570291, 1e-6);
  EXPECT_NEAR(l2.intercept, -0.310061, 1e-6);
}

TEST(AnkleOpenLoop, Algorithm1RecoversInsideAndSaturatesOutside) {
  const BalanceParams p;
  const double w = p.omega();
  const ComState inside{0.0, 0.5};  // capture point 0.0903 < 0.103
  const AnkleOpenLoopResult in = ankle_open_loop(p, inside);
  EXPECT_TRUE(in.recoverable);
  EXPECT_NEAR(in.zmp, 0.5 / w, 1e-12);
  EXPECT_NEAR(lipm_state(inside, w, in.forcing, 5.0).x, in.final_x, 1e-7);

  const ComState outside{0.0, 0.6};  // capture point 0.1084 > 0.103
  const AnkleOpenLoopResult out = ankle_open_loop(p, outside);
  EXPECT_FALSE(out.recoverable);
  EXPECT_DOUBLE_EQ(out.zmp, p.zmp_max);
  EXPECT_GT(lipm_state(outside, w, out.forcing, 3.0).x, 1.0);  // falls forward

  // States exactly on l1 / l2 are the last recoverable ones.
  EXPECT_TRUE(ankle_open_loop(p, {0.02, ankle_front_boundary(p).velocity_at(0.02)}).recoverable);
  EXPECT_TRUE(ankle_open_loop(p, {0.02, ankle_back_boundary(p).velocity_at(0.02)}).recoverable);
  EXPECT_FALSE(
      ankle_open_loop(p, {0.02, ankle_back_boundary(p).velocity_at(0.02) - 1e-6}).recoverable);
}

TEST(AnkleClosedLoop, IntersectionsLieOnTheirLinesWithZmpAtTheBorder) {
  const BalanceParams p;
  const PdGains k{10, 10};  // Fig. 7.5
  const ClosedLoopBoundaries c = closed_loop_boundaries(p, k);
  EXPECT_NEAR(c.k1, 10 * 0.32 / 9.81, 1e-12);
  EXPECT_NEAR(c.k2, 1 + 10 * 0.32 / 9.81, 1e-12);
  ASSERT_TRUE(c.A && c.B && c.C && c.D);
  struct Case {
    PhasePoint pt;
    double zmp_open, zmp_pd;
  };
  for (const Case& cs : {Case{*c.A, p.zmp_max, p.zmp_max}, Case{*c.B, p.zmp_max, p.zmp_min},
                         Case{*c.C, p.zmp_min, p.zmp_max}, Case{*c.D, p.zmp_min, p.zmp_min}}) {
    EXPECT_NEAR(capture_point({cs.pt.x, cs.pt.v}, p.omega()), cs.zmp_open, 1e-12);
    EXPECT_NEAR(pd_demanded_zmp(p, k, {cs.pt.x, cs.pt.v}, 0.0), cs.zmp_pd, 1e-12);
  }
  // A = l1 x a has x = x_max (1 - omega k1) / (k2 - omega k1).
  const double w = p.omega();
  EXPECT_NEAR(c.A->x, p.zmp_max * (1 - w * c.k1) / (c.k2 - w * c.k1), 1e-12);
}

TEST(AnkleClosedLoop, Fig76cGainsMakeTheLinesParallel) {
  // a, b parallel to l1, l2 when k2 / k1 = omega, i.e. kp = omega kd - omega^2 = 80.08 for kd = 20.
  const BalanceParams p;
  const double w = p.omega();
  const double kp = w * 20 - w * w;
  EXPECT_NEAR(kp, 80.08, 0.005);
  const ClosedLoopBoundaries c = closed_loop_boundaries(p, {kp, 20});
  EXPECT_FALSE(c.A.has_value());
  EXPECT_FALSE(c.D.has_value());
  EXPECT_NEAR(c.a.slope, c.l1.slope, 1e-9);
}

TEST(AnkleClosedLoop, PdClosedFormMatchesRk4ForAllDampingCases) {
  for (const PdGains k : {PdGains{72, 12}, PdGains{36, 12}, PdGains{10, 20}}) {
    const ComState s0{0.03, -0.2};
    const double x_set = 0.01;
    const std::function<OdeState<2>(double, const OdeState<2>&)> rhs = [&](double,
                                                                           const OdeState<2>& y) {
      return OdeState<2>{y[1], k.kp * (x_set - y[0]) - k.kd * y[1]};  // Eq. 7.16
    };
    OdeState<2> y{s0.x, s0.v};
    const int steps = 4000;
    const double h = 2.0 / steps;
    for (int i = 0; i < steps; ++i) y = rk4_step<2>(rhs, i * h, y, h);
    const ComState exact = pd_state(k, s0, x_set, 2.0);
    EXPECT_NEAR(exact.x, y[0], 1e-10) << "kp " << k.kp << " kd " << k.kd;
    EXPECT_NEAR(exact.v, y[1], 1e-10) << "kp " << k.kp << " kd " << k.kd;
  }
}

TEST(AnkleClosedLoop, UnsaturatedSimulationFollowsThePdClosedForm) {
  BalanceParams wide;  // a sole so long that Eq. 7.19 never clips: pure Eq. 7.16 dynamics
  wide.zmp_min = -10;
  wide.zmp_max = 10;
  const PdGains k{72, 12};
  const ComState s0{-0.4, 2.3};
  const ClosedLoopRun run = simulate_closed_loop(wide, k, s0, 0.0, 1.0, 1e-3);
  EXPECT_FALSE(run.saturated);
  for (const ClosedLoopSample& s : run.samples) {
    const ComState exact = pd_state(k, s0, 0.0, s.t);
    ASSERT_NEAR(s.x, exact.x, 1e-9) << "t = " << s.t;
    ASSERT_NEAR(s.ankle_torque, wide.mass * wide.g * s.zmp, 1e-12);  // Eq. 7.10
  }
}

TEST(AnkleClosedLoop, Fig77InitialStatesWithSaturatedZmp) {
  // kp = 72, kd = 12 (Fig. 7.7). The thesis reports (a,b) and (c,d) converging, (e,f) and (g,h)
  // diverging. With the ZMP clipped to the printed sole [-0.056, 0.103], (a,b), (e,f), (g,h)
  // agree; (c,d) = (0.42, -2.3) converges only with the sole mirrored to [-0.103, 0.056].
  const BalanceParams p;
  const PdGains k{72, 12};
  auto converges = [&](const BalanceParams& q, ComState s) {
    return simulate_closed_loop(q, k, s, 0.0, 4.0, 1e-3).converged;
  };
  EXPECT_TRUE(converges(p, {-0.4, 2.3}));
  EXPECT_FALSE(converges(p, {-0.32, 2.3}));
  EXPECT_FALSE(converges(p, {0.37, -2.3}));
  EXPECT_FALSE(converges(p, {0.42, -2.3}));
  BalanceParams mirrored = p;
  mirrored.zmp_min = -p.zmp_max;
  mirrored.zmp_max = -p.zmp_min;
  EXPECT_TRUE(converges(mirrored, {0.42, -2.3}));
  EXPECT_FALSE(converges(mirrored, {0.37, -2.3}));
  // Every Fig. 7.7 start demands a ZMP outside the sole at t = 0 (outside the a-b band).
  for (const ComState s :
       {ComState{-0.4, 2.3}, ComState{0.42, -2.3}, ComState{-0.32, 2.3}, ComState{0.37, -2.3}}) {
    const double z = pd_demanded_zmp(p, k, s, 0.0);
    EXPECT_TRUE(z < p.zmp_min || z > p.zmp_max);
  }
}

TEST(AnkleClosedLoop, RejectsNonPositiveDerivativeGain) {
  EXPECT_THROW(closed_loop_boundaries(BalanceParams{}, {72, 0}), Error);
  EXPECT_THROW(simulate_closed_loop(BalanceParams{}, {72, 12}, {}, 0, 1, 0), Error);
}

}  // namespace
}  // namespace stride::balance
