// A hinge carries its stops into ODE only within reach of them, and a servo driving a joint
// past its range still ends on the stop.
#include <cmath>

#include <gtest/gtest.h>

#include "robot/hal/joint_id.hpp"
#include "simulator/world/ode/ode_robot_body.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

using hal::JointId;

std::unique_ptr<sim::Simulation> hung_nao() {
  return test::scene_from_text(R"(<scene><ground enabled="false"/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml"
           xyz="0 0 1" fixed="true"><joints LKneePitch="0.5"/><sensors noise="off"/></robot></scene>)");
}

TEST(JointStops, InOdeOnlyWithinReach) {
  auto sim = hung_nao();
  sim->run_for(0.01);
  const auto& robot = sim->robot(0);
  const auto& model = robot.model();
  const auto& body = dynamic_cast<const sim::OdeRobotBody&>(robot.body());
  dJointID head = body.joint(model.joint_index("HeadYaw"));  // at 0, 2.09 rad from both
  EXPECT_TRUE(std::isinf(dJointGetHingeParam(head, dParamLoStop)));
  EXPECT_TRUE(std::isinf(dJointGetHingeParam(head, dParamHiStop)));
  // The elbow rolls stand at 0, beyond their range (-1.54, -0.035): their stops are in place.
  const int elbow = model.joint_index("LElbowRoll");
  dJointID id = body.joint(elbow);
  EXPECT_DOUBLE_EQ(dJointGetHingeParam(id, dParamLoStop), model.joints[elbow].lower);
  EXPECT_DOUBLE_EQ(dJointGetHingeParam(id, dParamHiStop), model.joints[elbow].upper);
}

TEST(JointStops, ServoDrivenPastTheRangeEndsOnTheStop) {
  auto sim = hung_nao();
  auto& robot = sim->robot(0);
  const int knee = robot.model().joint_index("LKneePitch");
  const double lower = robot.model().joints[knee].lower;  // -0.092 rad
  hal::ActuatorFrame cmd = robot.latest_commands();
  cmd.position[hal::index(JointId::LKneePitch)] = -1.0;  // far past it
  robot.write(cmd);
  dJointID id = dynamic_cast<const sim::OdeRobotBody&>(robot.body()).joint(knee);
  sim->step();
  EXPECT_TRUE(std::isinf(dJointGetHingeParam(id, dParamLoStop)));  // 0.5 rad: out of reach
  sim->run_for(1.0);
  EXPECT_NEAR(robot.body().joint_position(knee), lower, 0.01);
  EXPECT_DOUBLE_EQ(dJointGetHingeParam(id, dParamLoStop), lower);
}

}  // namespace
}  // namespace stride
