#pragma once
// Representations of the thesis' online posture control (Ch. 4): calibrated gyro rates, the
// estimated torso state, the posture-corrected joint targets and the arm-swing shoulder targets.
#include <array>

#include <Eigen/Core>

#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {

// Gyro rates about the torso x (roll) and y (pitch) axes with the running offset removed.
struct CalibratedGyro {
  STRIDE_FIELDS(CalibratedGyro);
  // calibrated, of Eq. 4.3 and Eq. 4.4
  STRIDE_FIELD(Eigen::Vector2d, rate, "rad/s") = Eigen::Vector2d::Zero();
  // (C_x, C_y) of Eq. 4.1 and Eq. 4.2
  STRIDE_FIELD(Eigen::Vector2d, offset, "rad/s") = Eigen::Vector2d::Zero();

  static constexpr std::string_view kTypeName = "CalibratedGyro";
};

// Kalman estimate of the torso orientation and rate, state order of Eq. 4.5:
// [pitch, roll, pitch_rate, roll_rate]. Pitch > 0 leans forward, roll > 0 leans right.
struct TorsoState {
  STRIDE_FIELDS(TorsoState);
  STRIDE_FIELD(double, pitch, "rad") = 0;
  STRIDE_FIELD(double, roll, "rad") = 0;
  STRIDE_FIELD(double, pitch_rate, "rad/s") = 0;
  STRIDE_FIELD(double, roll_rate, "rad/s") = 0;
  STRIDE_FIELD(Eigen::Vector4d, variance) = Eigen::Vector4d::Zero();  // diagonal of P_{k|k}
  STRIDE_FIELD(Eigen::Vector4d, gain) = Eigen::Vector4d::Zero();      // diagonal of K_k

  Eigen::Vector4d state() const { return {pitch, roll, pitch_rate, roll_rate}; }

  static constexpr std::string_view kTypeName = "TorsoState";
};

// The walking joint targets after the hip or ankle strategy (or passed through unchanged).
struct PostureCorrectedRequest {
  STRIDE_FIELDS(PostureCorrectedRequest);
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), position, "rad", {}, hal::kJointNames){};
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), stiffness, "", Range{0, 1},
               hal::kJointNames){};
  // Delta theta of Eq. 4.8 or Eq. 4.12, thesis sign
  STRIDE_FIELD(double, pitch_correction, "rad") = 0;
  // Delta phi of Eq. 4.9 or Eq. 4.13, thesis sign
  STRIDE_FIELD(double, roll_correction, "rad") = 0;

  static constexpr std::string_view kTypeName = "PostureCorrectedRequest";
};

// Shoulder pitch targets that compensate the swing leg's yaw moment (Sec. 4.4).
struct ArmSwingRequest {
  STRIDE_FIELDS(ArmSwingRequest);
  STRIDE_FIELD(double, left_shoulder_pitch, "rad") = 0;
  STRIDE_FIELD(double, right_shoulder_pitch, "rad") = 0;
  // x_a of Eq. 4.20 for each arm, forward > 0
  STRIDE_FIELD(double, left_arm_displacement, "m") = 0;
  STRIDE_FIELD(double, right_arm_displacement, "m") = 0;

  static constexpr std::string_view kTypeName = "ArmSwingRequest";
};

}  // namespace stride
