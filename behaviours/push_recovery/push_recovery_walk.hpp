#pragma once
// Push recovery while walking (thesis Sec. 8.2 future work, through joint positions only):
//   PushRecoveryWalk  FrameInfo, JointSensorData, ComState, BalanceModel
//                     -> WalkingJointRequest, PushRecoveryState
// The Ch. 3 walk of PatternWalk, watched by a push detector: the CoM state (ComStateEstimator
// with follow_support, origin under the stance sole) minus the plan's, held against the Ch. 7
// boundaries (push_detector.hpp), switches in the balance response through joint positions:
//   ankle      stance ankle offsets from the capture-point deviation (the CoP moves with it),
//   hip        the bang-bang HAT excursion (Eq. 7.24, Eq. 7.26, Eq. 7.27) on both hip pitch joints,
//   combined   both (Eq. 7.37),
//   step       past the Ch. 7 boundaries: the swing foot lands nearer the capture point and the
//              pattern is re-planned from there (AdjustedPattern), the waist lowered for reach.
// The posture modules of Ch. 4 (HipStrategy, AnkleStrategy) run downstream as usual.
#include <Eigen/Core>

#include "behaviours/push_recovery/push_detector.hpp"
#include "behaviours/walking/modules/walk_parameters.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"

namespace stride {

struct PushRecoveryState {
  STRIDE_FIELDS(PushRecoveryState);
  // this frame's classification, x
  STRIDE_FIELD(behaviours::PushResponse, sagittal) = behaviours::PushResponse::none;
  // y (ankle or step: Ch. 7 is sagittal)
  STRIDE_FIELD(behaviours::PushResponse, lateral) = behaviours::PushResponse::none;
  STRIDE_FIELD(Eigen::Vector2d, deviation, "m") = Eigen::Vector2d::Zero();  // m, CoM - plan
  STRIDE_FIELD(Eigen::Vector2d, deviation_rate, "m/s") = Eigen::Vector2d::Zero();
  // m, of the capture point
  STRIDE_FIELD(Eigen::Vector2d, capture_deviation, "m") = Eigen::Vector2d::Zero();
  // m, from the stance ankle
  STRIDE_FIELD(Eigen::Vector2d, planned_zmp, "m") = Eigen::Vector2d::Zero();
  // rad: stance pitch, roll
  STRIDE_FIELD(Eigen::Vector2d, ankle_offset, "rad") = Eigen::Vector2d::Zero();
  // rad, trunk forward
  STRIDE_FIELD(double, hat_angle, "rad") = 0;
  // landings moved so far
  STRIDE_FIELD(int, steps_moved) = 0;
  // m, the walk moved in all
  STRIDE_FIELD(Eigen::Vector2d, walk_offset, "m") = Eigen::Vector2d::Zero();
  // s, first frame not none
  STRIDE_FIELD(double, first_detection, "s") = -1;
  STRIDE_FIELD(double, gait_phase) = 0;  // 0..1 of the stride

  static constexpr std::string_view kTypeName = "PushRecoveryState";
};

}  // namespace stride

namespace stride::behaviours {

struct PushRecoveryParameters {
  STRIDE_FIELDS(PushRecoveryParameters);
  STRIDE_FIELD(bool, enabled) = true;  // false: the plain pattern, PatternWalk's targets exactly
  // m of capture-point deviation that is the walk's own (the unpushed medium walk on the 3 mm
  // floor reaches -0.061..0.025 m forward and -0.069..0.054 m sideways)
  STRIDE_FIELD(double, threshold, "m", Range{0, 0.5}) = 0.07;
  STRIDE_FIELD(double, lateral_threshold, "m", Range{0, 0.5}) = 0.08;
  STRIDE_FIELD(bool, hip) = true;  // sagittal hip and combined responses allowed
  // m of capture-point deviation beyond which the stance ankle acts (per axis); the thresholds
  // above gate the hip, combined and step responses only. Sagittally the ankle acts from 2 cm,
  // before a push is classified (at 7 cm, the first measurement, it came too late: README);
  // sideways from the lateral threshold (acting on the walk's own +-5 cm sway lost more walks).
  STRIDE_FIELD(double, ankle_threshold, "m", Range{0, 0.5}) = 0.02;
  STRIDE_FIELD(double, ankle_lateral_threshold, "m", Range{0, 0.5}) = 0.08;
  // rad per m of capture-point deviation beyond the threshold
  STRIDE_FIELD(double, ankle_pitch_gain, "rad/m", Range{0, 20}) = 1.5;
  STRIDE_FIELD(double, ankle_roll_gain, "rad/m", Range{0, 20}) = 1.5;
  STRIDE_FIELD(double, max_ankle, "rad", Range{0, 0.5}) = 0.12;
  // N m, both hips together (HipBalance's)
  STRIDE_FIELD(double, tau_forward, "N*m", Range{0.01, 100}) = 14;
  STRIDE_FIELD(double, tau_backward, "N*m", Range{-100, -0.01}) = -14;
  STRIDE_FIELD(double, max_hat, "rad", Range{0, 1}) = 0.35;
  STRIDE_FIELD(double, hat_hold_time, "s", Range{0, 5}) = 0.15;
  STRIDE_FIELD(double, hat_return_time, "s", Range{0.01, 5}) = 0.4;
  STRIDE_FIELD(double, step_gain, "", Range{0, 3}) = 1.0;
  STRIDE_FIELD(double, max_forward, "m", Range{0, 0.15}) = 0.04;
  STRIDE_FIELD(double, max_backward, "m", Range{0, 0.15}) = 0.03;
  STRIDE_FIELD(double, max_outward, "m", Range{0, 0.15}) = 0.04;
  STRIDE_FIELD(double, max_inward, "m", Range{0, 0.1}) = 0.01;
  // s a swing must have left to be moved
  STRIDE_FIELD(double, min_swing_time, "s", Range{0, 1}) = 0.06;
  // m: smaller moves of a landing are not made
  STRIDE_FIELD(double, step_tolerance, "m", Range{0, 0.1}) = 0.008;
  // m the waist is lowered for a recovery step
  STRIDE_FIELD(double, lower, "m", Range{0, 0.06}) = 0.015;
  STRIDE_FIELD(double, lower_hold, "s", Range{0, 10}) = 0.5;
  STRIDE_FIELD(double, lower_return, "s", Range{0.01, 10}) = 0.5;
  // s before the walk over which the CoM-waist offset is learned
  STRIDE_FIELD(double, com_offset_time, "s", Range{0.01, 10}) = 0.5;

  StepLimits limits() const { return {max_forward, max_backward, max_outward, max_inward}; }

  static constexpr std::string_view kTypeName = "PushRecoveryParameters";
};

// The walk (PatternWalk's parameters) and the recovery, as `walk.<field>` and `recovery.<field>`.
struct PushRecoveryWalkParameters {
  STRIDE_FIELDS(PushRecoveryWalkParameters);
  STRIDE_FIELD(WalkParameters, walk);
  STRIDE_FIELD(PushRecoveryParameters, recovery);

  static constexpr std::string_view kTypeName = "PushRecoveryWalkParameters";
};

void register_push_recovery_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
