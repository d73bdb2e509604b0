// Combined ankle + hip strategy (Eqs. 7.31-7.37, Fig. 7.11).
#include "behaviours/balance/combined_strategy.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stride::balance {
namespace {

TEST(CombinedStrategy, BoundariesAddTheSoleToTheHipShift) {
  const BalanceParams p;
  const CombinedBoundaries c = combined_boundaries(p);
  const HipBoundaries h = hip_boundaries(p);
  EXPECT_NEAR(c.forward, 0.103 + h.forward, 1e-15);  // Eq. 7.37
  EXPECT_NEAR(c.backward, -0.056 + h.backward, 1e-15);
  EXPECT_NEAR(c.forward, 0.164374, 1e-6);
  EXPECT_NEAR(c.backward, -0.077750, 1e-6);
}

TEST(CombinedStrategy, Fig711InitialStates) {
  const BalanceParams p;
  const double w = p.omega();
  const BangBangPlan green = plan_combined(p, {0.0, 0.8});
  EXPECT_TRUE(green.recoverable);
  EXPECT_DOUBLE_EQ(green.zmp, p.zmp_max);
  // T from the closed form after Eq. 7.36.
  const double T = -std::log(1 - std::sqrt(p.mass * p.g / p.tau_forward * (0.8 / w - 0.103))) / w;
  EXPECT_NEAR(green.profile.t1, T, 1e-12);
  EXPECT_NEAR(green.profile.t1, 0.081481, 1e-5);
  EXPECT_NEAR(green.profile.t2, 2 * T, 1e-12);
  EXPECT_LT(green.theta_peak, p.theta_max_forward);
  const HipModelState late = bang_bang_state(p, {0.0, 0.8}, green, 3.0);
  EXPECT_NEAR(late.x, p.zmp_max, 1e-6);  // rests over the front border of the sole
  EXPECT_NEAR(late.v, 0.0, 1e-5);

  const BangBangPlan red = plan_combined(p, {0.0, 1.1});
  EXPECT_FALSE(red.recoverable);
  EXPECT_GT(bang_bang_state(p, {0.0, 1.1}, red, 3.0).x, 1.0);
}

TEST(CombinedStrategy, InsideTheSoleNoHipTorqueIsNeeded) {
  const BangBangPlan plan = plan_combined(BalanceParams{}, {0.0, 0.3});
  EXPECT_TRUE(plan.recoverable);
  EXPECT_DOUBLE_EQ(plan.profile.tau, 0.0);
}

}  // namespace
}  // namespace stride::balance
