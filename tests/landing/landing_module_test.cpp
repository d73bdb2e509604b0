// Ch. 6's landing controllers as modules: the planned descent stops at its end, the impedance law
// with the sole on target and at rest asks only for g(theta) (which, on the hung leg, is what the
// simulator's statics need), and `mr` swaps LandingImpedance for LandingPosition on the rig.
#include <gtest/gtest.h>

#include "behaviours/landing/landing_law.hpp"
#include "console/session/sim_session.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/link_poses.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/runtime/runtime.hpp"
#include "simulator/world/gravity_torque.hpp"

namespace stride::landing {
namespace {

const std::string kRig = STRIDE_SOURCE_DIR "/scenes/landing/landing_nao.xml";

TEST(LandingPlan, SinksAtItsSpeedAndStopsAtTheEnd) {
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  start.translation() << 0.01, 0.05, -0.30;
  const SoleTarget early = planned_sole(start, 0.2, -0.33, 0.1);
  EXPECT_NEAR(early.pose.translation().z(), -0.32, 1e-12);
  EXPECT_EQ(early.velocity, Eigen::Vector3d(0, 0, -0.2));
  EXPECT_EQ(early.pose.translation().x(), 0.01);
  const SoleTarget late = planned_sole(start, 0.2, -0.33, 0.5);
  EXPECT_EQ(late.pose.translation().z(), -0.33);
  EXPECT_EQ(late.velocity, Eigen::Vector3d::Zero());
}

TEST(ImpedanceLaw, OnTargetAtRestOnlyGravityIsLeftAndItMatchesTheSimulatorsStatics) {
  console::SimSession session(kRig);
  const sim::SimulatedRobot& robot = session.simulation().robot(0);
  const model::RobotModel& m = robot.model();
  Eigen::VectorXd q_model = model::zero_joints(m);
  model::LegAngles q{};
  const LegGravityModel leg = left_leg_gravity_model(m);
  for (std::size_t j = 0; j < m.joints.size(); ++j)
    if (m.joints[j].movable())
      q_model[static_cast<Eigen::Index>(j)] = robot.body().joint_position(static_cast<int>(j));
  for (int i = 0; i < 6; ++i) q[i] = q_model[leg.joint[i]];
  const model::LegAngles g = leg_gravity_torques(m, leg, q_model, {0, 0, -9.81});
  // The simulator's own sum over its bodies' world poses (the torso is level on the rig).
  const char* names[] = {"LHipYawPitch", "LHipRoll",    "LHipPitch",
                         "LKneePitch",   "LAnklePitch", "LAnkleRoll"};
  const char* links[] = {"LPelvis", "LHip", "LThigh", "LTibia", "LAnkle", "LFoot"};
  EXPECT_GT(std::abs(g[2]), 0.1);  // the hip pitch carries the whole leg
  for (int j = 1; j < 6; ++j) {
    double expected = 0;
    for (int k = j; k < 6; ++k)
      expected -= sim::gravity_torque_about_joint(robot.body(), names[j], {links[k]});
    EXPECT_NEAR(g[j], expected, 1e-3 * std::max(1.0, std::abs(expected))) << names[j];
  }
  const SoleTarget here{model::leg_fk(model::Side::Left, q), Eigen::Vector3d::Zero()};
  const model::LegAngles tau = impedance_torques(ImpedanceGains{}, here, q, {}, g);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(tau[i], g[i], 1e-9);
}

TEST(LandingModules, MrSwapsTheImpedanceLawForThePositionControlledLeg) {
  console::SimSession session(kRig);
  Runtime& runtime = *session.runtime(0);
  EXPECT_EQ(runtime.provider_of("JointRequest"), "LandingImpedance");
  session.simulation().run_for(0.05);
  runtime.swap_provider("JointRequest", "LandingPosition");
  session.simulation().run_for(0.05);
  EXPECT_EQ(runtime.provider_of("JointRequest"), "LandingPosition");
  EXPECT_EQ(runtime.representation<JointRequest>().mode[hal::index(hal::JointId::LKneePitch)],
            hal::ServoMode::Position);
}

}  // namespace
}  // namespace stride::landing
