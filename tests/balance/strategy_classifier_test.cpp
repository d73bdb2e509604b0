// Strategy classifier over the Ch. 7 boundaries.
#include "behaviours/balance/strategy_classifier.hpp"

#include <gtest/gtest.h>

#include "robot/core/error.hpp"

namespace stride::balance {
namespace {

TEST(StrategyClassifier, PicksTheLeastEffortStrategy) {
  const BalanceParams p;
  EXPECT_EQ(classify(p, {0.02, 0.4}).strategy, Strategy::ankle);     // capture point 0.0922
  EXPECT_EQ(classify(p, {0.0, 0.8}).strategy, Strategy::combined);   // Fig. 7.11 green
  EXPECT_EQ(classify(p, {0.0, 1.1}).strategy, Strategy::none);       // Fig. 7.11 red
  EXPECT_EQ(classify(p, {0.0, -0.55}).strategy, Strategy::none);     // beyond -0.0778
  EXPECT_EQ(classify(p, {0.0, -0.4}).strategy, Strategy::combined);  // -0.0722
}

TEST(StrategyClassifier, HipWinsWhenItsRegionExceedsTheSole) {
  BalanceParams p;
  p.zmp_min = -0.005;  // a narrow sole (e.g. standing on a beam)
  p.zmp_max = 0.005;
  const Classification c = classify(p, {0.0, 0.2});  // capture point 0.0361
  EXPECT_FALSE(c.ankle_recovers);
  EXPECT_TRUE(c.hip_recovers);
  EXPECT_EQ(c.strategy, Strategy::hip);
}

TEST(StrategyClassifier, IntervalsAreNested) {
  const Classification c = classify(BalanceParams{}, {});
  EXPECT_LE(c.combined.lo, c.ankle.lo);
  EXPECT_GE(c.combined.hi, c.ankle.hi);
  EXPECT_LE(c.combined.lo, c.hip.lo);
  EXPECT_GE(c.combined.hi, c.hip.hi);
  EXPECT_EQ(to_string(Strategy::combined), "combined");
}

TEST(StrategyClassifier, BadParametersNameTheField) {
  BalanceParams p;
  p.tau_backward = 3;
  try {
    classify(p, {});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("tau_backward"), std::string::npos);
  }
}

}  // namespace
}  // namespace stride::balance
