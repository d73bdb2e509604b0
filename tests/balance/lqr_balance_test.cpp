// LQR balance of the combined model (Eqs. 7.38-7.39, Figs. 7.13-7.14).
#include "behaviours/balance/lqr_balance.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stride::balance {
namespace {

TEST(LqrBalance, ModelMatricesFollowEq738) {
  const BalanceParams p;
  const LqrBalanceModel m = lqr_balance_model(p);
  const double w2 = 9.81 / 0.32;
  EXPECT_DOUBLE_EQ(m.A(0, 2), 1);
  EXPECT_DOUBLE_EQ(m.A(1, 3), 1);
  EXPECT_NEAR(m.A(2, 0), w2, 1e-12);
  EXPECT_NEAR(m.B(2, 0), -w2, 1e-12);
  EXPECT_NEAR(m.B(2, 1), -1 / (p.mass * p.z_cm), 1e-12);
  EXPECT_NEAR(m.B(3, 1), 1 / p.inertia, 1e-12);
  EXPECT_EQ((m.A.row(3).array() != 0).count(), 0);
}

TEST(LqrBalance, Fig713PushIsRegulatedBackToTheOrigin) {
  const BalanceParams p;
  const LqrBalanceModel m = lqr_balance_model(p);
  const Eigen::Matrix4d Q = thesis_lqr_q();
  const Eigen::Matrix2d R = thesis_lqr_r();
  const LqrSolution sol = lqr(m.A, m.B, Q, R);
  EXPECT_LT(care_residual(m.A, m.B, Q, R, sol.S).norm(), 1e-6 * sol.S.norm());
  EXPECT_LT(sol.closed_loop_poles.real().maxCoeff(), 0.0);

  const Eigen::Vector4d x0(0, 0, 0.9475, 0);  // (x0, theta0, xdot0, thetadot0) of Fig. 7.13
  const double dt = 1e-3;
  const auto run = simulate_lqr(m, sol.K, x0, 8.0, dt);
  EXPECT_LT(run.back().state.norm(), 1e-6);  // back at the origin
  double peak_x = 0, cost = 0;
  for (std::size_t i = 0; i < run.size(); ++i) {
    peak_x = std::max(peak_x, std::abs(run[i].state(0)));
    const double c = run[i].state.dot(Q * run[i].state) + run[i].input.dot(R * run[i].input);
    cost += (i == 0 || i + 1 == run.size() ? 0.5 : 1.0) * c * dt;  // trapezoid
  }
  EXPECT_GT(peak_x, 0.0);
  EXPECT_LT(peak_x, 0.9475 / p.omega());  // better than the free pendulum's capture point
  // Optimal cost: integral of x'Qx + u'Ru equals x0' S x0 (Eq. 7.39 times 2).
  EXPECT_NEAR(cost, x0.dot(sol.S * x0), 1e-4 * x0.dot(sol.S * x0));  // trapezoid, dt = 1 ms
}

}  // namespace
}  // namespace stride::balance
