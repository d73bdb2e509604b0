#pragma once
// Thesis Ch. 4 online posture control as modules, and their parameters:
//   GyroCalibration        InertialSensorData -> CalibratedGyro               (Sec. 4.3.1)
//   TorsoStateEstimator    InertialSensorData, CalibratedGyro -> TorsoState   (Sec. 4.3.2)
//   HipStrategy | AnkleStrategy | NoPostureControl
//                          WalkingJointRequest, TorsoState -> PostureCorrectedRequest (4.3.3)
//   ArmSwing               WalkingJointRequest -> ArmSwingRequest            (Sec. 4.4)
//   WalkingJointRequestAssembler  PostureCorrectedRequest, ArmSwingRequest -> JointRequest
//   (LandingControl, behaviours/landing, takes the assembler's place with landing control)
#include <array>

#include "behaviours/posture/arm_swing.hpp"
#include "behaviours/posture/posture_correction.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {
struct ArmSwingRequest;
struct JointRequest;
}  // namespace stride

namespace stride::behaviours {

// The walk's final targets: every joint from the leg targets, in position mode, but the
// shoulder pitches from arm swing.
void assemble_walking_request(const std::array<double, hal::kNumJoints>& position,
                              const std::array<double, hal::kNumJoints>& stiffness,
                              const ArmSwingRequest& arms, JointRequest& out);

struct GyroCalibrationParameters {
  STRIDE_FIELDS(GyroCalibrationParameters);
  STRIDE_FIELD(double, alpha, "", Range{0, 1}) = 0.001;  // Sec. 4.3.1
  // C starts at the first raw sample, as if the robot had stood long enough for the offset
  // of Eq. 4.1 and Eq. 4.2 to settle (1/alpha = 10 s at 10 ms); false starts it at 0.
  STRIDE_FIELD(bool, start_at_first_sample) = true;

  static constexpr std::string_view kTypeName = "GyroCalibrationParameters";
};

// Q, R and P_{0|0} = L * I as chosen in Sec. 4.3.2; state order [pitch, roll, rates].
struct TorsoStateEstimatorParameters {
  STRIDE_FIELDS(TorsoStateEstimatorParameters);
  STRIDE_FIELD(Eigen::Vector4d, q_diagonal, "", Range{0, 1e6}){1e-1, 1e-1, 1e-5, 1e-5};
  STRIDE_FIELD(Eigen::Vector4d, r_diagonal, "", Range{1e-12, 1e6}){1e-4, 1e-4, 1e-3, 1e-3};
  STRIDE_FIELD(double, initial_variance, "", Range{0, 1e9}) = 1000;  // L

  static constexpr std::string_view kTypeName = "TorsoStateEstimatorParameters";
};

// PD gains on the torso error and the desired torso inclination; desired rates are zero.
// Defaults: the thesis' printed gains in its own signs, which are ours (posture_correction.hpp):
// hip strategy as in Figs. 4.7-4.8 (K_p = 0.40, K_d = -0.05), ankle strategy as in
// Figs. 4.11-4.12 (K_p = 0.28, K_d = -0.06); the thesis gives one pair per strategy, used here
// for pitch (K_p1, K_d1) and roll (K_p2, K_d2) alike.
template <PostureJoints Joints>
struct PostureStrategyParameters {
  STRIDE_FIELDS(PostureStrategyParameters);
  static constexpr bool kHip = Joints == PostureJoints::Hip;
  STRIDE_FIELD(double, kp_pitch, "", Range{-5, 5}) = kHip ? 0.40 : 0.28;
  STRIDE_FIELD(double, kd_pitch, "s", Range{-1, 1}) = kHip ? -0.05 : -0.06;
  STRIDE_FIELD(double, kp_roll, "", Range{-5, 5}) = kHip ? 0.40 : 0.28;
  STRIDE_FIELD(double, kd_roll, "s", Range{-1, 1}) = kHip ? -0.05 : -0.06;
  STRIDE_FIELD(double, desired_pitch, "rad", Range{-0.5, 0.5}) = 0;
  STRIDE_FIELD(double, desired_roll, "rad", Range{-0.5, 0.5}) = 0;

  PostureGains gains() const { return {kp_pitch, kd_pitch, kp_roll, kd_roll}; }

  static constexpr std::string_view kTypeName =
      kHip ? "HipStrategyParameters" : "AnkleStrategyParameters";
};
using HipStrategyParameters = PostureStrategyParameters<PostureJoints::Hip>;
using AnkleStrategyParameters = PostureStrategyParameters<PostureJoints::Ankle>;

// Sec. 4.4 model with NAO numbers: swing leg = thigh + tibia + foot as in the thesis' Ch. 5
// (0.3897 + 0.2914 + 0.1618 kg); each arm = shoulder..hand links of the V5 URDF (nao-facts.md);
// d_0 = 50 mm (Table 4.3); d_1 = ShoulderOffsetY; d_a = arm CoM from the shoulder (V5 URDF).
struct ArmSwingParameters {
  STRIDE_FIELDS(ArmSwingParameters);
  STRIDE_FIELD(double, swing_leg_mass, "kg", Range{0, 10}) = 0.8429;
  STRIDE_FIELD(double, arm_mass, "kg", Range{0.01, 10}) = 0.57858;
  STRIDE_FIELD(double, foot_half_distance, "m", Range{0, 0.5}) = 0.050;
  STRIDE_FIELD(double, arm_half_distance, "m", Range{0.01, 0.5}) = 0.098;
  STRIDE_FIELD(double, arm_com_distance, "m", Range{0.01, 0.5}) = 0.0952;
  STRIDE_FIELD(double, gain_scale, "", Range{0, 5}) = 1.0;  // 0 turns arm swing off

  ArmSwingModel model() const {
    return {swing_leg_mass,     arm_mass,          arm_mass,
            foot_half_distance, arm_half_distance, arm_com_distance};
  }

  static constexpr std::string_view kTypeName = "ArmSwingParameters";
};

void register_posture_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
