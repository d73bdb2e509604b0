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
  Eigen::Vector2d rate = Eigen::Vector2d::Zero();    // calibrated, of Eq. 4.3 and Eq. 4.4
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  // (C_x, C_y) of Eq. 4.1 and Eq. 4.2

  static constexpr std::string_view kTypeName = "CalibratedGyro";
  static constexpr auto fields() {
    return std::make_tuple(field("rate", &CalibratedGyro::rate, "rad/s"),
                           field("offset", &CalibratedGyro::offset, "rad/s"));
  }
};

// Kalman estimate of the torso orientation and rate, state order of Eq. 4.5:
// [pitch, roll, pitch_rate, roll_rate]. Pitch > 0 leans forward, roll > 0 leans right.
struct TorsoState {
  double pitch = 0;
  double roll = 0;
  double pitch_rate = 0;
  double roll_rate = 0;
  Eigen::Vector4d variance = Eigen::Vector4d::Zero();  // diagonal of P_{k|k}
  Eigen::Vector4d gain = Eigen::Vector4d::Zero();      // diagonal of K_k

  Eigen::Vector4d state() const { return {pitch, roll, pitch_rate, roll_rate}; }

  static constexpr std::string_view kTypeName = "TorsoState";
  static constexpr auto fields() {
    using S = TorsoState;
    return std::make_tuple(field("pitch", &S::pitch, "rad"), field("roll", &S::roll, "rad"),
                           field("pitch_rate", &S::pitch_rate, "rad/s"),
                           field("roll_rate", &S::roll_rate, "rad/s"),
                           field("variance", &S::variance), field("gain", &S::gain));
  }
};

// The walking joint targets after the hip or ankle strategy (or passed through unchanged).
struct PostureCorrectedRequest {
  std::array<double, hal::kNumJoints> position{};
  std::array<double, hal::kNumJoints> stiffness{};
  double pitch_correction = 0;  // Delta theta of Eq. 4.8 or Eq. 4.12, thesis sign
  double roll_correction = 0;   // Delta phi of Eq. 4.9 or Eq. 4.13, thesis sign

  static constexpr std::string_view kTypeName = "PostureCorrectedRequest";
  static constexpr auto fields() {
    using P = PostureCorrectedRequest;
    return std::make_tuple(
        field("position", &P::position, "rad").named(hal::kJointNames),
        field("stiffness", &P::stiffness, "", Range{0, 1}).named(hal::kJointNames),
        field("pitch_correction", &P::pitch_correction, "rad"),
        field("roll_correction", &P::roll_correction, "rad"));
  }
};

// Shoulder pitch targets that compensate the swing leg's yaw moment (Sec. 4.4).
struct ArmSwingRequest {
  double left_shoulder_pitch = 0;
  double right_shoulder_pitch = 0;
  double left_arm_displacement = 0;  // x_a of Eq. 4.20 for each arm, forward > 0
  double right_arm_displacement = 0;

  static constexpr std::string_view kTypeName = "ArmSwingRequest";
  static constexpr auto fields() {
    using A = ArmSwingRequest;
    return std::make_tuple(field("left_shoulder_pitch", &A::left_shoulder_pitch, "rad"),
                           field("right_shoulder_pitch", &A::right_shoulder_pitch, "rad"),
                           field("left_arm_displacement", &A::left_arm_displacement, "m"),
                           field("right_arm_displacement", &A::right_arm_displacement, "m"));
  }
};

}  // namespace stride
