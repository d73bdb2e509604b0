// Simulated devices: servo torque mode, motor currents from torque, encoder quantisation, IMU,
// the opt-in compliant servo.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "robot/hal/joint_id.hpp"
#include "simulator/world/gravity_torque.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

using hal::JointId;

std::string hanging_nao(const std::string& extra_joints, const std::string& sensors = "",
                        const std::string& physics = "") {
  return R"(<scene><ground enabled="false"/>)" + physics + R"(
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml"
           xyz="0 0 1" fixed="true"><joints )" +
         extra_joints + "/>" + sensors + "</robot></scene>";
}

// The hung NAO (exact solver, no noise) with `motor` changes to its device file in the scene.
std::string hung_nao_with(const std::string& motor) {
  return R"(<scene><ground enabled="false"/><physics solver="exact"/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml"
           xyz="0 0 1" fixed="true"><joints LHipPitch="-0.6"/><sensors noise="off"/>)" +
         motor + "</robot></scene>";
}

// The hung left leg's hip after `seconds`: its angle and the gravity torque about it.
struct HungHip {
  int joint;
  double q, tau;
};
HungHip settle_hung_hip(sim::Simulation& sim, double seconds) {
  sim.run_for(seconds);
  auto& robot = sim.robot(0);
  const int j = robot.model().joint_index("LHipPitch");
  return {j, robot.body().joint_position(j),
          sim::gravity_torque_about_joint(robot.body(), "LHipPitch",
                                          {"LThigh", "LTibia", "LAnkle", "LFoot"})};
}

// A spring of K N*m/rad sags under the hung leg's gravity torque tau by tau / K, where the
// velocity servo holds the target exactly.
TEST(Devices, CompliantServoSagsByGravityTorqueOverSpring) {
  const double spring = 60;
  auto sim = test::scene_from_text(hung_nao_with(R"(<motor name="pitch" spring="60"/>)"));
  const auto [j, q, tau] = settle_hung_hip(*sim, 3.0);
  EXPECT_GT(std::abs(tau), 0.3);
  // The servo's torque balances gravity: spring * (target - q) + tau = 0.
  EXPECT_NEAR(spring * (-0.6 - q), -tau, 0.02 * std::abs(tau));
  EXPECT_GT(std::abs(q + 0.6), 0.005);  // a visible sag, unlike the stiff servo

  auto stiff = test::scene_from_text(hung_nao_with(""));
  stiff->run_for(3.0);
  EXPECT_NEAR(stiff->robot(0).body().joint_position(j), -0.6, 1e-3);
}

// Integral action (the thesis' PID joint servos) takes the sag out: the error's integral grows
// until it alone carries the gravity torque, so the joint settles on its target.
TEST(Devices, CompliantServoIntegralActionRemovesTheSag) {
  const double spring = 60;  // integral 240: the sag closes at about 240 / 60 = 4 per second
  auto sim =
      test::scene_from_text(hung_nao_with(R"(<motor name="pitch" spring="60" integral="240"/>)"));
  const auto [j, q, tau] = settle_hung_hip(*sim, 4.0);
  const double sag = std::abs(tau) / spring;  // what the spring alone leaves
  EXPECT_GT(sag, 0.005);
  EXPECT_LT(std::abs(q + 0.6), 0.02 * sag) << "q " << q << ", sag without integral " << sag;
}

// Strong damping brings the hung leg to a new target without overshoot; a tenth of the
// back-EMF damping lets it overshoot.
TEST(Devices, CompliantServoDampingSetsTheOvershoot) {
  auto overshoot = [](const std::string& damping) {
    auto sim = test::scene_from_text(
        hung_nao_with(R"(<motor name="pitch" spring="200" damping=")" + damping + R"("/>)"));
    auto& robot = sim->robot(0);
    const int j = robot.model().joint_index("LHipPitch");
    sim->run_for(2.0);
    const double rest = robot.body().joint_position(j);
    hal::ActuatorFrame cmd = robot.latest_commands();
    cmd.position[hal::index(JointId::LHipPitch)] += 0.1;
    robot.write(cmd);
    double furthest = 0;
    for (int k = 0; k < 150; ++k) {
      sim->run_for(0.01);
      furthest = std::max(furthest, robot.body().joint_position(j) - rest);
    }
    return furthest / 0.1 - 1;
  };
  EXPECT_LT(overshoot("8"), 0.02);
  EXPECT_GT(overshoot("0.12"), 0.05);
}

// With gear play b, gravity leans the hung leg on one flank of the gear: the joint settles b / 2
// from the target, on the side gravity pulls it to; the stiff servo holds the target.
TEST(Devices, BacklashLetsGravityTakeUpHalfThePlay) {
  const double play = 2 * std::numbers::pi / 180;
  auto sim = test::scene_from_text(hung_nao_with(R"(<motor name="pitch" backlash="2deg"/>)"));
  auto& robot = sim->robot(0);
  const auto [j, q, tau] = settle_hung_hip(*sim, 2.0);
  // Gravity turns the raised leg (hip pitch -0.6) back towards hanging: towards larger angles.
  EXPECT_GT(std::abs(tau), 0.3);
  EXPECT_NEAR(q, -0.6 + play / 2, 0.1 * play);
  // Within the play the joint is free: a small push moves it without the servo resisting.
  hal::ActuatorFrame cmd = robot.latest_commands();
  cmd.position[hal::index(JointId::LHipPitch)] = -0.6 + play;  // gear moves by the whole play
  robot.write(cmd);
  sim->run_for(1.0);
  EXPECT_NEAR(robot.body().joint_position(j), -0.6 + 1.5 * play, 0.1 * play);
}

TEST(Devices, TorqueModeWithZeroTorqueLetsTheLegSwingDown) {
  auto sim = test::scene_from_text(hanging_nao(R"(LHipPitch="-0.6")"));
  auto& robot = sim->robot(0);
  hal::ActuatorFrame cmd = robot.latest_commands();
  cmd.mode[hal::index(JointId::LHipPitch)] = hal::ServoMode::Torque;
  cmd.torque[hal::index(JointId::LHipPitch)] = 0;
  robot.write(cmd);
  sim->run_for(0.15);
  // Gravity pulls the raised leg back towards hanging (hip pitch -> 0).
  const int j = robot.model().joint_index("LHipPitch");
  EXPECT_GT(robot.body().joint_position(j), -0.45);
}

// The exact solver: at 20 iterations the iterative solver's joint forces are about 11 % off
// (bench/solver_tradeoff_bench).
TEST(Devices, PositionModeHoldsAndCurrentIsTorqueOverGearAndMotorConstant) {
  auto sim = test::scene_from_text(hanging_nao(R"(LHipPitch="-0.6")", R"(<sensors noise="off"/>)",
                                               R"(<physics solver="exact"/>)"));
  auto& robot = sim->robot(0);
  sim->run_for(1.0);
  const int j = robot.model().joint_index("LHipPitch");
  EXPECT_NEAR(robot.body().joint_position(j), -0.6, 0.02);
  // Static torque about the hip pitch axis from gravity on everything below it.
  const double tau = std::abs(sim::gravity_torque_about_joint(
      robot.body(), "LHipPitch", {"LThigh", "LTibia", "LAnkle", "LFoot"}));
  const double expected_current = tau / (130.85 * 0.0068);  // pitch motor in nao.devices.xml
  const double current = robot.latest_sensors().current[hal::index(JointId::LHipPitch)];
  EXPECT_GT(expected_current, 0.2);
  EXPECT_NEAR(current, expected_current, 0.05 * expected_current);
}

// A calibration error of the servo: commanded -0.6, the joint stands at -0.6 + offset while the
// encoder reads -0.6; the other leg's servo has none.
TEST(Devices, ServoOffsetMovesTheJointAndNotItsEncoder) {
  const double offset = 3 * std::numbers::pi / 180;
  std::string scene = hung_nao_with(R"(<servo joint="LHipPitch" offset="3deg"/>)");
  scene.insert(scene.find("LHipPitch=\"-0.6\""), "RHipPitch=\"-0.6\" ");
  auto sim = test::scene_from_text(scene);
  sim->run_for(1.0);
  auto& robot = sim->robot(0);
  const auto& model = robot.model();
  EXPECT_NEAR(robot.body().joint_position(model.joint_index("LHipPitch")), -0.6 + offset, 1e-3);
  EXPECT_NEAR(robot.body().joint_position(model.joint_index("RHipPitch")), -0.6, 1e-3);
  const auto& encoders = robot.latest_sensors().position;
  const double lsb = 2 * std::numbers::pi / 4096;
  EXPECT_NEAR(encoders[hal::index(JointId::LHipPitch)], -0.6, lsb);
  EXPECT_NEAR(encoders[hal::index(JointId::RHipPitch)], -0.6, lsb);
}

// A spring on one joint's servo (<servo joint="LHipPitch" spring="60"/>) sags that joint by
// tau / K and leaves the other hip, on the same motor of the device file, on its stiff target.
TEST(Devices, ServoSpringChangesOnlyItsJoint) {
  const double spring = 60;
  std::string scene = hung_nao_with(R"(<servo joint="LHipPitch" spring="60"/>)");
  scene.insert(scene.find("LHipPitch=\"-0.6\""), "RHipPitch=\"-0.6\" ");
  auto sim = test::scene_from_text(scene);
  const auto [j, q, tau] = settle_hung_hip(*sim, 3.0);
  EXPECT_GT(std::abs(tau), 0.3);
  EXPECT_NEAR(spring * (-0.6 - q), -tau, 0.02 * std::abs(tau));
  const int right = sim->robot(0).model().joint_index("RHipPitch");
  EXPECT_NEAR(sim->robot(0).body().joint_position(right), -0.6, 1e-3);
}

TEST(Devices, EncodersQuantiseToTwelveBits) {
  auto sim = test::scene_from_text(hanging_nao(R"(LKneePitch="0.5")"));
  sim->run_for(0.05);
  const double step = 2 * std::numbers::pi / 4096;
  for (double q : sim->robot(0).latest_sensors().position) {
    const double k = q / step;
    EXPECT_NEAR(k, std::round(k), 1e-6);
  }
}

TEST(Devices, ImuOfAStandingRobotReadsGravityAndTheGyroBias) {
  auto sim = test::scene_from_text(R"(<scene><physics seed="2"/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml">
      <joints LHipPitch="-0.3" RHipPitch="-0.3" LKneePitch="0.6" RKneePitch="0.6"
              LAnklePitch="-0.3" RAnklePitch="-0.3" LShoulderPitch="1.5" RShoulderPitch="1.5"/>
    </robot></scene>)");
  sim->run_for(0.5);
  Eigen::Vector3d acc = Eigen::Vector3d::Zero(), gyro = Eigen::Vector3d::Zero();
  const int n = 200;
  for (int k = 0; k < n; ++k) {
    sim->run_for(0.01);
    const auto& s = sim->robot(0).latest_sensors();
    acc += Eigen::Vector3d(s.accelerometer[0], s.accelerometer[1], s.accelerometer[2]) / n;
    gyro += Eigen::Vector3d(s.gyroscope[0], s.gyroscope[1], s.gyroscope[2]) / n;
  }
  EXPECT_NEAR(acc.norm(), 9.81, 0.05);
  EXPECT_GT(acc.z(), 9.7);
  const double bias = -18 * std::numbers::pi / 180;  // nao.devices.xml, as the thesis saw
  EXPECT_NEAR(gyro.x(), bias, 0.005);
  EXPECT_NEAR(gyro.y(), bias, 0.005);
  EXPECT_NEAR(gyro.z(), 0.0, 0.005);
}

// The gyro reads the time derivative of the torso angles (NAOqi signs, the Kalman filter's model,
// Eq. 4.6): a NAO pushed forward and rocking back turns both the same way.
TEST(Devices, GyroIsTheRateOfTheTorsoAngles) {
  auto sim = test::scene_from_text(R"(<scene><physics seed="3"/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml">
      <joints LHipPitch="-0.3" RHipPitch="-0.3" LKneePitch="0.6" RKneePitch="0.6"
              LAnklePitch="-0.3" RAnklePitch="-0.3" LShoulderPitch="1.5" RShoulderPitch="1.5"/>
      <sensors noise="off" delay="off"/>
    </robot>
    <push robot="nao" body="torso" force="30 0 0" start="0.1" duration="0.1"/></scene>)");
  auto& robot = sim->robot(0);
  const double bias = -18 * std::numbers::pi / 180;
  double agree = 0, total = 0, largest = 0;
  for (int k = 0; k < 60; ++k) {
    const auto before = robot.torso_pose();
    sim->run_for(0.01);
    const auto after = robot.torso_pose();
    const double rate = (after.pitch - before.pitch) / 0.01;
    const double gyro = robot.latest_sensors().gyroscope[1] - bias;
    if (std::abs(rate) < 0.05) continue;
    largest = std::max(largest, std::abs(rate));
    agree += rate * gyro > 0;
    ++total;
  }
  EXPECT_GT(largest, 0.3);  // it did rock
  EXPECT_GT(total, 10);
  EXPECT_GE(agree / total, 0.9);
}

}  // namespace
}  // namespace stride
