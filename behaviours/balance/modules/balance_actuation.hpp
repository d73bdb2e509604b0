#pragma once
// From the thesis' inverted-pendulum quantities to NAO joint commands (sagittal plane).
//   ZMP x_zmp  -> ankle pitch torque m g x_zmp (Eq. 7.10), half per ankle, servo torque mode.
//   HAT angle theta -> hip pitch position stand - theta (trunk forward is hip flexion, < 0).
#include <array>

#include "robot/hal/joint_id.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {

using JointAngles = std::array<double, hal::kNumJoints>;

// Every joint in position mode at `posture`.
void hold_posture(JointRequest& r, const JointAngles& posture, double stiffness);

// The torque of Eq. 7.10 on both ankle pitch joints; a positive joint torque presses the toes down,
// so it moves the CoP forward. `mass` is what the ankles carry.
void command_ankle_zmp(JointRequest& r, double zmp_x, double mass, double g);

// Both hip pitch joints at the posture's angle minus theta.
void command_hat_angle(JointRequest& r, const JointAngles& posture, double theta);

// The whole body tilted forward by `tilt` about the ankles (both ankle pitch joints, position).
void command_body_tilt(JointRequest& r, const JointAngles& posture, double tilt);

// HAT angle from the measured hip pitch joints (mean of both sides).
double measured_hat_angle(const JointSensorData& joints, const JointAngles& posture);

// Smooth 0..1 ramp with zero slope at both ends, for returning to the posture.
double smooth_ramp(double s);

}  // namespace stride::behaviours
