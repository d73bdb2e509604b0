// The simulated NAO: holds its standing pose with stiffness, collapses without, and its force
// sensors weigh it.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "robot/hal/joint_id.hpp"
#include "robot/nao/nao_dimensions.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

std::string stand_scene(double stiffness, bool noise) {
  return R"(<scene><physics seed="3"/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml" stiffness=")" +
         std::to_string(stiffness) + R"(">
      <joints LHipPitch="-0.3" RHipPitch="-0.3" LKneePitch="0.6" RKneePitch="0.6"
              LAnklePitch="-0.3" RAnklePitch="-0.3" LShoulderPitch="1.5" RShoulderPitch="1.5"
              LShoulderRoll="0.1" RShoulderRoll="-0.1" LElbowRoll="-0.05" RElbowRoll="0.05"/>
      <sensors noise=")" +
         (noise ? "on" : "off") + R"("/>
    </robot></scene>)";
}

class NaoStanding : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<sim::Simulation> scene(double stiffness, bool noise) const {
    return test::scene_from_text(test::on_engine(stand_scene(stiffness, noise), GetParam()));
  }
};

TEST_P(NaoStanding, StiffRobotStandsTenSecondsWithLittleDrift) {
  auto sim = scene(1.0, true);
  sim->run_for(0.5);  // let the contacts settle
  const auto p0 = sim->robot(0).torso_pose();
  sim->run_for(10.0);
  const auto p1 = sim->robot(0).torso_pose();
  const double drift =
      std::sqrt(std::pow(p1.x - p0.x, 2) + std::pow(p1.y - p0.y, 2) + std::pow(p1.z - p0.z, 2));
  RecordProperty("torso_drift_m", std::to_string(drift));
  EXPECT_LT(drift, 0.01);
  EXPECT_FALSE(sim->robot(0).fallen());
  EXPECT_GT(p1.z, 0.25);  // standing: hip-to-sole about 0.29 m with bent knees, torso 85 mm above
}

TEST_P(NaoStanding, LimpRobotCollapses) {
  auto sim = scene(0.0, false);
  const auto p0 = sim->robot(0).torso_pose();
  sim->run_for(3.0);
  const auto p1 = sim->robot(0).torso_pose();
  EXPECT_LT(p1.z, p0.z - 0.1) << "without stiffness the torso must drop";
}

TEST_P(NaoStanding, FootSensorsWeighTheRobotAndCopLiesUnderTheFeet) {
  auto sim = scene(1.0, false);
  sim->run_for(2.0);
  const auto& robot = sim->robot(0);
  const double weight = robot.model().total_mass() * 9.81;
  double sum = 0, left = 0, right = 0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  // The CoP in the world: every sensor at its world position, weighted by its force.
  for (int f = 0; f < 2; ++f) {
    const int foot = robot.model().link_index(f == 0 ? "LFoot" : "RFoot");
    const Eigen::Isometry3d pose = robot.body().link_pose(foot);
    for (int k = 0; k < 4; ++k) {
      const double force = robot.latest_sensors().fsr[f * 4 + k];
      const Eigen::Vector2d p = nao::kFsrPositions[f * 4 + k];
      const Eigen::Vector3d w = pose * Eigen::Vector3d(p.x(), p.y(), -nao::kFootHeight);
      sum += force;
      (f == 0 ? left : right) += force;
      moment += force * w.head<2>();
    }
  }
  RecordProperty("fsr_sum_N", std::to_string(sum));
  RecordProperty("weight_N", std::to_string(weight));
  EXPECT_NEAR(sum, weight, 0.03 * weight);
  EXPECT_NEAR(left, right, 0.2 * weight);
  const Eigen::Vector2d cop = moment / sum;
  // Support polygon of two parallel feet: x within the soles, y between the outer edges.
  const auto lpose = robot.body().link_pose(robot.model().link_index("LFoot"));
  const auto rpose = robot.body().link_pose(robot.model().link_index("RFoot"));
  const double x_min = lpose.translation().x() + nao::kSoleCentreX - nao::kSoleLength / 2;
  const double x_max = lpose.translation().x() + nao::kSoleCentreX + nao::kSoleLength / 2;
  EXPECT_GT(cop.x(), x_min);
  EXPECT_LT(cop.x(), x_max);
  EXPECT_LT(cop.y(), lpose.translation().y() + nao::kSoleCentreYLeft + nao::kSoleWidth / 2);
  EXPECT_GT(cop.y(), rpose.translation().y() - nao::kSoleCentreYLeft - nao::kSoleWidth / 2);
}

// The servo holds a joint that carries the robot's weight at its command, as ODE's motor row does:
// leaning sideways and forward loads the ankles with the body's weight (ODE 0.56 mrad behind).
// A servo whose strength came from the foot's own inertia (MuJoCo's first port) stood 2.7 mrad
// behind here and 0.04-0.3 rad behind on a walk's loaded ankle roll, and every walk fell.
TEST_P(NaoStanding, LoadedAnkleServosHoldTheirCommand) {
  using hal::JointId;
  auto sim = scene(1.0, false);
  auto& robot = sim->robot(0);
  sim->run_for(0.5);
  hal::ActuatorFrame cmd = robot.latest_commands();
  for (JointId j : {JointId::LAnkleRoll, JointId::RAnkleRoll}) cmd.position[hal::index(j)] += 0.08;
  for (JointId j : {JointId::LHipRoll, JointId::RHipRoll}) cmd.position[hal::index(j)] -= 0.08;
  for (JointId j : {JointId::LAnklePitch, JointId::RAnklePitch})
    cmd.position[hal::index(j)] -= 0.05;
  robot.write(cmd);
  sim->run_for(1.0);
  double worst = 0;
  for (JointId j :
       {JointId::LAnkleRoll, JointId::RAnkleRoll, JointId::LAnklePitch, JointId::RAnklePitch}) {
    const int joint = robot.model().joint_index(std::string(hal::name(j)));
    worst =
        std::max(worst, std::abs(cmd.position[hal::index(j)] - robot.body().joint_position(joint)));
  }
  RecordProperty("worst_ankle_error_rad", std::to_string(worst));
  EXPECT_LT(worst, 1e-3);
  EXPECT_FALSE(robot.fallen());
}

INSTANTIATE_TEST_SUITE_P(Engines, NaoStanding, ::testing::ValuesIn(test::engines()),
                         test::engine_name);

}  // namespace
}  // namespace stride
