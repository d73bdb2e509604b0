// Standing balance through joint positions: the strategy chosen at the Ch. 7 boundaries (least
// effort first, combined as the best effort past them all), the forced choices, the CoP's torque
// error and the HAT excursion's trunk-tilt compensation.
#include <cmath>

#include <gtest/gtest.h>

#include "behaviours/balance/modules/hat_excursion.hpp"
#include "behaviours/balance/modules/position_balance.hpp"
#include "behaviours/balance/strategy_classifier.hpp"

namespace stride::behaviours {
namespace {

using balance::Strategy;

// The strategy PositionBalance (auto) meets a push with when the push leaves capture point `xi`.
Strategy chosen_at(const balance::BalanceParams& p, double xi) {
  return chosen_strategy(BalanceChoice::automatic,
                         balance::classify(p, {0.0, xi * p.omega()}).strategy);
}

TEST(PositionBalanceChoice, TheSolesEdgeIsTheAnkleBoundary) {
  const balance::BalanceParams p;  // Ch. 7's robot: the hip region lies within the sole
  const balance::Classification c = balance::classify(p, {});
  EXPECT_EQ(c.ankle.hi, p.zmp_max);  // Eq. 7.13
  EXPECT_EQ(c.ankle.lo, p.zmp_min);
  EXPECT_LT(c.hip.hi, c.ankle.hi);
  EXPECT_EQ(chosen_at(p, p.zmp_max - 1e-4), Strategy::ankle);
  EXPECT_EQ(chosen_at(p, p.zmp_max + 1e-4), Strategy::combined);  // Eq. 7.37
  EXPECT_EQ(chosen_at(p, p.zmp_min + 1e-4), Strategy::ankle);
  EXPECT_EQ(chosen_at(p, p.zmp_min - 1e-4), Strategy::combined);
  // Past the combined boundary nothing recovers: combined as the best effort.
  EXPECT_EQ(balance::classify(p, {0.0, (c.combined.hi + 1e-3) * p.omega()}).strategy,
            Strategy::none);
  EXPECT_EQ(chosen_at(p, c.combined.hi + 1e-3), Strategy::combined);
}

TEST(PositionBalanceChoice, OnANarrowSoleTheHipBoundaryComesBetween) {
  balance::BalanceParams p;
  p.zmp_min = -0.005;
  p.zmp_max = 0.005;
  const balance::Classification c = balance::classify(p, {});
  ASSERT_GT(c.hip.hi, p.zmp_max + 2e-3);
  EXPECT_EQ(chosen_at(p, p.zmp_max - 1e-4), Strategy::ankle);
  EXPECT_EQ(chosen_at(p, p.zmp_max + 1e-3), Strategy::hip);  // Eq. 7.30
  EXPECT_EQ(chosen_at(p, c.hip.hi - 1e-4), Strategy::hip);
  EXPECT_EQ(chosen_at(p, c.hip.hi + 1e-4), Strategy::combined);
}

TEST(PositionBalanceChoice, AForcedStrategyIsKeptWhateverTheBoundariesSay) {
  EXPECT_EQ(chosen_strategy(BalanceChoice::ankle, Strategy::combined), Strategy::ankle);
  EXPECT_EQ(chosen_strategy(BalanceChoice::hip, Strategy::ankle), Strategy::hip);
  EXPECT_EQ(chosen_strategy(BalanceChoice::combined, Strategy::none), Strategy::combined);
}

TEST(PositionBalanceAnkle, TheCopErrorIsTheAnkleTorqueOfEq710) {
  // 4.9 kg above the ankles, CoP 1 cm behind the demanded ZMP: 0.48 N m to push it forward.
  EXPECT_NEAR(cop_torque_error(4.9, 9.81, 0.03, 0.02), 0.480690, 1e-6);
  EXPECT_NEAR(cop_torque_error(4.9, 9.81, 0.0, 0.02), -0.961380, 1e-6);
}

TEST(HatExcursion, TheBodyTiltTakesBackTheTrunksCarriedCoM) {
  BalanceModel m;
  m.mass = 5.3;
  m.hat_mass = 3.2;
  m.hat_inertia = 3.2 * 0.1 * 0.1;  // d = 10 cm
  m.com_height = 0.3;
  // A trunk 0.2 rad forward carries the CoM 3.2 * 0.1 * sin(0.2) / 5.3 = 12.0 mm ahead.
  const double tilt = com_keeping_tilt(m, 0.2);
  EXPECT_NEAR(tilt * m.com_height, -3.2 * 0.1 * std::sin(0.2) / 5.3, 1e-12);
  EXPECT_NEAR(tilt, -0.039983, 1e-6);
}

}  // namespace
}  // namespace stride::behaviours
