// SwingLegTracking, Sec. 5.4.2's controller as a module: its control step is the Ch. 5 laws (on
// the reference with the true parameters the adaptive torque is the leg's inverse dynamics), the
// encoder angles are differentiated for q', and a sweep varies the module's gains.
#include <sstream>

#include <gtest/gtest.h>

#include "behaviours/joint_state/joint_velocities.hpp"
#include "behaviours/swing_leg/swing_leg_tracking.hpp"
#include "console/sweep/sweep_engine.hpp"
#include "console/sweep/sweep_parser.hpp"
#include "robot/model/dynamics/swing_leg_3d.hpp"

namespace stride::swing_leg {
namespace {

TEST(SwingLegTrackingStep, OnTheReferenceWithTrueParametersTheTorqueIsTheInverseDynamics) {
  const Leg17 a = model::leg3d_parameters(model::thesis_3d_leg());
  Leg5 q, qd, qdd;
  q << 0.05, -0.4, 0.8, -0.4, -0.05;
  qd << 0.1, -0.6, 1.2, -0.6, -0.1;
  qdd << -0.3, 2.0, -4.0, 2.0, 0.3;
  const JointReference<5> on_target{q, qd, qdd};
  const LegTrackingStep s =
      leg3d_tracking_step(Controller::Adaptive, q, qd, on_target, a, 20, 0.1, thesis_ode_gamma());
  const model::Leg3dTerms t = model::leg3d_terms(q, qd, a);
  const Leg5 inverse_dynamics = t.inertia * qdd + t.coriolis * qd + t.gravity;  // Eq. 5.4
  EXPECT_LT((s.tau - inverse_dynamics).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(s.a_hat_rate.cwiseAbs().maxCoeff(), 1e-12);  // s = 0: nothing to learn
}

TEST(SwingLegTrackingStep, PdIsEq514WithKpLambdaKd) {
  Leg5 q = Leg5::Zero(), qd = Leg5::Zero();
  const JointReference<5> target{Leg5::Constant(0.1), Leg5::Constant(0.5), Leg5::Zero()};
  const LegTrackingStep s =
      leg3d_tracking_step(Controller::Pd, q, qd, target, Leg17::Zero(), 20, 0.1, Leg17::Ones());
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(s.tau[i], 20 * 0.1 * 0.1 + 0.1 * 0.5);  // 0.25 N m
  EXPECT_EQ(s.a_hat_rate, Leg17::Zero());
}

TEST(JointVelocityEstimator, BackwardDifferenceOverThePeriod) {
  std::array<double, hal::kNumJoints> before{}, now{};
  now[3] = 0.002;
  before[5] = 0.01;
  const auto v = behaviours::backward_difference(before, now, 0.001);
  EXPECT_DOUBLE_EQ(v[3], 2.0);
  EXPECT_DOUBLE_EQ(v[5], -10.0);
  EXPECT_DOUBLE_EQ(v[0], 0.0);
}

// The hung NAO of the study, its gains as a sweep factor: the module reads each run's gain and
// the runs differ.
TEST(SwingLegTrackingModule, ASweepVariesItsGains) {
  const sweep::Sweep s(
      sweep::parse_sweep_text(R"(<sweep name="track" scenes="../../scenes">
  <scene file="swing_leg/hanging_nao.xml"/>
  <set target="SwingLegTracking.controller" value="pd"/>
  <factor name="lambda" target="SwingLegTracking.lambda" values="10 40"/>
  <run seconds="1.2"/>
  <record>
    <value name="lambda_read" key="module:SwingLegTracking.lambda"/>
    <value name="hash" key="sim.hash"/>
    <value name="knee" key="representation:JointSensorData.position[3]"/>
  </record>
</sweep>)",
                              std::string(STRIDE_SOURCE_DIR) + "/tests/swing_leg/track.sweep.xml"));
  sweep::SweepOptions o;
  o.print_tallies = o.plots = false;
  std::ostringstream text;
  const auto executor = sweep::in_process_executor();
  const sweep::SweepResult r = sweep::run_sweep(s, sweep::Tallies(s), *executor, o, text);
  ASSERT_EQ(r.rows.size(), 2u);
  const auto header = s.csv_header();
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  EXPECT_EQ(r.rows[0][column("status")], "ok") << r.rows[0].back();
  EXPECT_EQ(r.rows[0][column("lambda_read")], "10");
  EXPECT_EQ(r.rows[1][column("lambda_read")], "40");
  EXPECT_NE(r.rows[0][column("hash")], r.rows[1][column("hash")]);
}

}  // namespace
}  // namespace stride::swing_leg
