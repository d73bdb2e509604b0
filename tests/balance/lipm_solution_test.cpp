// LIPM closed form (Eqs. 7.12-7.15) against RK4 of the same ODE.
#include "behaviours/balance/lipm_solution.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stride::balance {
namespace {

ComState integrate_lipm(const ComState& s0, double omega, double f, double t_end, int steps) {
  const std::function<OdeState<2>(double, const OdeState<2>&)> rhs = [&](double,
                                                                         const OdeState<2>& y) {
    return OdeState<2>{y[1], omega * omega * y[0] + f};
  };
  OdeState<2> y{s0.x, s0.v};
  const double h = t_end / steps;
  for (int i = 0; i < steps; ++i) y = rk4_step<2>(rhs, i * h, y, h);
  return {y[0], y[1]};
}

TEST(LipmSolution, MatchesRk4WithConstantZmp) {
  const BalanceParams p;
  const double w = p.omega();
  for (const ComState s0 : {ComState{0.01, 0.2}, ComState{-0.03, 0.5}, ComState{0.05, -0.4}}) {
    for (const double zmp : {-0.05, 0.0, 0.08}) {
      const double f = ankle_forcing(zmp, w);
      const ComState exact = lipm_state(s0, w, f, 1.0);
      const ComState numeric = integrate_lipm(s0, w, f, 1.0, 2000);
      EXPECT_NEAR(exact.x, numeric.x, 1e-9 * std::max(1.0, std::abs(exact.x)));
      EXPECT_NEAR(exact.v, numeric.v, 1e-9 * std::max(1.0, std::abs(exact.v)));
    }
  }
}

TEST(LipmSolution, CapturePointZmpBringsCoMToRestOverIt) {
  // Eqs. 7.13-7.14: with x_zmp = x0 + xdot0/omega the CoM converges to x_zmp.
  const BalanceParams p;
  const double w = p.omega();
  const ComState s0{-0.02, 0.3};
  const double zmp = converging_zmp(s0, w);
  const ComState late = lipm_state(s0, w, ankle_forcing(zmp, w), 3.0);
  EXPECT_NEAR(late.x, zmp, 1e-8);
  EXPECT_NEAR(late.v, 0.0, 1e-7);
  // The capture point is invariant along that trajectory (text after Eq. 7.15).
  for (double t : {0.1, 0.5, 1.3})
    EXPECT_NEAR(capture_point(lipm_state(s0, w, ankle_forcing(zmp, w), t), w), zmp, 1e-12);
}

TEST(LipmSolution, ZeroTimeReturnsInitialState) {
  const ComState s = lipm_state({0.07, -0.3}, 5.0, 2.0, 0.0);
  EXPECT_DOUBLE_EQ(s.x, 0.07);
  EXPECT_DOUBLE_EQ(s.v, -0.3);
}

}  // namespace
}  // namespace stride::balance
