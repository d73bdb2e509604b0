// The Ch. 7 strategies on the simulated NAO: standing still, a small push the ankle absorbs, and
// a push so large that the models predict no strategy recovers, which the robot confirms.
#include <gtest/gtest.h>

#include <cmath>

#include "behaviours/balance/modules/balance_modules.hpp"
#include "behaviours/balance/modules/balance_outlook.hpp"
#include "behaviours/balance/modules/balance_representations.hpp"
#include "behaviours/balance/strategy_classifier.hpp"
#include "tests/push/push_scene.hpp"

namespace stride::push_test {
namespace {

Eigen::Vector2d left_foot(const sim::RobotBody& body) {
  return body.link_pose(body.model().link_index("LFoot")).translation().head<2>();
}

TEST(BalanceModules, EveryStrategyStandsStillWithoutPush) {
  for (const char* module : {"AnkleBalance", "HipBalance", "CombinedBalance", "LqrBalance"}) {
    auto session = balance_session(module);
    auto& sim = session->simulation();
    sim.run_for(1.5);
    EXPECT_FALSE(sim.robot(0).fallen()) << module;
    const ComState& c = session->runtime(0)->representation<ComState>();
    EXPECT_LT(std::abs(c.xdot), 0.02) << module;
    EXPECT_GT(c.x, -0.06) << module;  // CoM over the sole
    EXPECT_LT(c.x, 0.10) << module;
  }
}

TEST(BalanceModules, AnkleBalanceRecoversFromASmallPush) {
  auto session = balance_session("AnkleBalance");
  auto& sim = session->simulation();
  sim.run_for(1.0);
  const double x_before = session->runtime(0)->representation<ComState>().x;
  const Eigen::Vector2d foot = left_foot(sim.robot(0).body());
  sim.push("nao", "torso", Eigen::Vector3d(6, 0, 0), Eigen::Vector3d::Zero(), 0.05);  // 0.3 N s
  sim.run_for(0.09);
  const ComState& c = session->runtime(0)->representation<ComState>();
  const double v_after_push = c.xdot;
  EXPECT_GT(v_after_push, 0.02);
  sim.run_for(3.0);
  EXPECT_FALSE(sim.robot(0).fallen());
  EXPECT_LT((left_foot(sim.robot(0).body()) - foot).norm(), 0.02);
  // The PD brought the CoM back to where it stood (Eq. 7.16 with x_set) and to rest.
  EXPECT_NEAR(c.x, x_before, 0.01);
  EXPECT_LT(std::abs(true_com(sim.robot(0).body()).velocity.x()), 0.01);
}

TEST(BalanceModules, AVeryLargePushIsPredictedNoneAndFalls) {
  auto session = balance_session("AnkleBalance");
  auto& sim = session->simulation();
  sim.run_for(1.0);
  sim.push("nao", "torso", Eigen::Vector3d(160, 0, 0), Eigen::Vector3d::Zero(), 0.05);  // 8 N s
  sim.run_for(0.08);
  const auto& rt = *session->runtime(0);
  const ComState& c = rt.representation<ComState>();
  const behaviours::HipBalanceParameters hip;
  const auto params =
      balance_params(rt.representation<BalanceModel>(), hip.tau_forward, hip.tau_backward);
  const auto cls = balance::classify(params, {c.x, c.xdot});
  EXPECT_EQ(cls.strategy, balance::Strategy::none) << "capture point " << cls.capture_point;
  bool fell = false;
  for (int i = 0; i < 30 && !fell; ++i) {
    sim.run_for(0.1);
    fell = sim.robot(0).fallen();
  }
  EXPECT_TRUE(fell);
}

TEST(BalanceModules, TheOutlookStatesEachBoundaryAsACaptureInterval) {
  sim::SceneDescription scene = sim::parse_scene_file(scene_path());
  scene.robots[0].controller.providers["BalancePrediction"] = "BalanceOutlook";
  console::SimSession session(std::move(scene));
  session.simulation().run_for(0.5);
  const auto& rt = *session.runtime(0);
  const BalancePrediction& p = rt.representation<BalancePrediction>();
  const BalanceModel& m = rt.representation<BalanceModel>();
  const ComState& c = rt.representation<ComState>();
  ASSERT_TRUE(p.valid);
  EXPECT_NEAR(p.omega, std::sqrt(9.81 / m.com_height), 1e-12);  // Eq. 7.1
  EXPECT_NEAR(p.omega, 6.03, 0.05);                             // z_cm about 0.27 m standing
  EXPECT_NEAR(p.capture_point, c.x + c.xdot / p.omega, 1e-12);
  // The ankle's interval is the sole (Eq. 7.13): 6 cm behind to 10 cm ahead of the ankles.
  EXPECT_NEAR(p.ankle_lo, -0.06, 1e-9);
  EXPECT_NEAR(p.ankle_hi, 0.10, 1e-9);
  // The hip's and the combined intervals are those of Eqs. 7.30 and 7.37 for the outlook's
  // 14 N m hips; the combined one holds the other two.
  const balance::BalanceParams params = balance_params(m, 14, -14);
  const balance::HipBoundaries hip = balance::hip_boundaries(params);
  const balance::CombinedBoundaries both = balance::combined_boundaries(params);
  EXPECT_EQ(p.hip_lo, hip.backward);
  EXPECT_EQ(p.hip_hi, hip.forward);
  EXPECT_EQ(p.combined_lo, both.backward);
  EXPECT_EQ(p.combined_hi, both.forward);
  EXPECT_NEAR(p.hip_lo, -0.0233, 0.002);
  EXPECT_NEAR(p.hip_hi, 0.0338, 0.002);
  EXPECT_LT(p.combined_lo, std::min(p.ankle_lo, p.hip_lo));
  EXPECT_GT(p.combined_hi, std::max(p.ankle_hi, p.hip_hi));
}

}  // namespace
}  // namespace stride::push_test
