#include "behaviours/balance/modules/balance_actuation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stride::behaviours {

using hal::index;
using hal::JointId;

void hold_posture(JointRequest& r, const JointAngles& posture, double stiffness) {
  for (int i = 0; i < hal::kNumJoints; ++i) {
    r.mode[i] = hal::ServoMode::Position;
    r.position[i] = posture[i];
    r.stiffness[i] = stiffness;
    r.torque[i] = 0;
  }
}

void command_ankle_zmp(JointRequest& r, double zmp_x, double mass, double g) {
  const double per_ankle = 0.5 * mass * g * zmp_x;  // Eq. 7.10: tau_a = m g x_zmp
  for (JointId j : {JointId::LAnklePitch, JointId::RAnklePitch}) {
    r.mode[index(j)] = hal::ServoMode::Torque;
    r.torque[index(j)] = per_ankle;
  }
}

void command_hat_angle(JointRequest& r, const JointAngles& posture, double theta) {
  for (JointId j : {JointId::LHipPitch, JointId::RHipPitch}) {
    r.mode[index(j)] = hal::ServoMode::Position;
    r.position[index(j)] = posture[index(j)] - theta;
  }
}

void command_body_tilt(JointRequest& r, const JointAngles& posture, double tilt) {
  for (JointId j : {JointId::LAnklePitch, JointId::RAnklePitch}) {
    r.mode[index(j)] = hal::ServoMode::Position;
    r.position[index(j)] = posture[index(j)] - tilt;  // the foot stays, so the shin leans: -q
  }
}

double measured_hat_angle(const JointSensorData& joints, const JointAngles& posture) {
  double sum = 0;
  for (JointId j : {JointId::LHipPitch, JointId::RHipPitch})
    sum += posture[index(j)] - joints.position[index(j)];
  return sum / 2;
}

double smooth_ramp(double s) {
  return 0.5 - 0.5 * std::cos(std::numbers::pi * std::clamp(s, 0.0, 1.0));
}

}  // namespace stride::behaviours
