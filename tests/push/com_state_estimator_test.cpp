// ComStateEstimator on the simulated standing NAO: the filtered CoM state against the
// simulator's mass-weighted body state, at rest and while a push moves the robot.
#include <gtest/gtest.h>

#include "behaviours/balance/modules/balance_representations.hpp"
#include "tests/push/push_scene.hpp"

namespace stride::push_test {
namespace {

TEST(ComStateEstimator, ConvergesToTheStandingRobotsCom) {
  auto session = balance_session("AnkleBalance");
  auto& sim = session->simulation();
  sim.run_for(1.0);
  const ComState& est = session->runtime(0)->representation<ComState>();
  ASSERT_TRUE(est.valid);
  // Errors over the next 50 control frames; the encoders, IMU and FSRs are noisy.
  Eigen::Vector4d squared = Eigen::Vector4d::Zero();
  Eigen::Vector4d worst = Eigen::Vector4d::Zero();
  const int frames = 50;
  for (int i = 0; i < frames; ++i) {
    sim.run_for(0.01);
    const TrueCom truth = true_com(sim.robot(0).body());
    const Eigen::Vector4d e(est.x - truth.position.x(), est.y - truth.position.y(),
                            est.xdot - truth.velocity.x(), est.ydot - truth.velocity.y());
    squared += e.cwiseAbs2();
    worst = worst.cwiseMax(e.cwiseAbs());
    EXPECT_NEAR(est.com_height, truth.position.z(), 0.01);
  }
  const Eigen::Vector4d rms = (squared / frames).cwiseSqrt();
  // Stated accuracy: position within 3 mm RMS (5 mm worst), velocity within 2.5 cm/s RMS (the
  // filter is tuned to follow pushes quickly, which lets encoder and IMU noise through).
  EXPECT_LT(rms(0), 0.003);
  EXPECT_LT(rms(1), 0.003);
  EXPECT_LT(worst(0), 0.005);
  EXPECT_LT(worst(1), 0.005);
  EXPECT_LT(rms(2), 0.025);
  EXPECT_LT(rms(3), 0.025);
  // The filtered ZMP stays under the resting CoM.
  EXPECT_NEAR(est.zmp_x, est.x, 0.01);
}

TEST(ComStateEstimator, TracksTheVelocityAPushGives) {
  auto session = balance_session("AnkleBalance");
  auto& sim = session->simulation();
  sim.run_for(1.0);
  sim.push("nao", "torso", Eigen::Vector3d(8, 0, 0), Eigen::Vector3d::Zero(), 0.05);  // 0.4 N s
  sim.run_for(0.09);  // the filter follows the velocity jump within a few frames
  const ComState& est = session->runtime(0)->representation<ComState>();
  const TrueCom truth = true_com(sim.robot(0).body());
  ASSERT_GT(truth.velocity.x(), 0.02);  // the push did move the CoM forward
  EXPECT_NEAR(est.xdot, truth.velocity.x(), 0.3 * truth.velocity.x());
  EXPECT_NEAR(est.x, truth.position.x(), 0.005);
}

TEST(ComStateEstimator, BalanceModelHasTheRobotsNumbers) {
  auto session = balance_session("AnkleBalance");
  session->simulation().run_for(0.05);
  const BalanceModel& m = session->runtime(0)->representation<BalanceModel>();
  ASSERT_TRUE(m.valid);
  EXPECT_NEAR(m.mass, session->simulation().robot(0).model().total_mass(), 1e-9);
  EXPECT_LT(m.mass_above_ankles, m.mass);
  EXPECT_GT(m.com_height, 0.2);  // knees bent, below the stretched NAO's ~0.32 m
  EXPECT_LT(m.com_height, 0.33);
  EXPECT_DOUBLE_EQ(m.zmp_min, -0.060);  // sole in nao_dimensions.hpp
  EXPECT_DOUBLE_EQ(m.zmp_max, 0.100);
  const auto& model = session->simulation().robot(0).model();
  const auto& hip = model.joints[model.joint_index("LHipPitch")];
  // Hip pitch ROM seen from the standing posture's -0.3 rad (theta = trunk forward).
  EXPECT_NEAR(m.theta_max_forward, -0.3 - hip.lower, 1e-3);
  EXPECT_NEAR(m.theta_max_backward, -0.3 - hip.upper, 1e-3);
  EXPECT_GT(m.hat_inertia, 0.005);
}

}  // namespace
}  // namespace stride::push_test
