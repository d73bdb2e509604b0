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
  behaviours::PushResponse sagittal =
      behaviours::PushResponse::none;  // this frame's classification, x
  behaviours::PushResponse lateral =
      behaviours::PushResponse::none;                        // y (ankle or step: Ch. 7 is sagittal)
  Eigen::Vector2d deviation = Eigen::Vector2d::Zero();       // m, CoM - plan
  Eigen::Vector2d deviation_rate = Eigen::Vector2d::Zero();  // m/s
  Eigen::Vector2d capture_deviation = Eigen::Vector2d::Zero();  // m, of the capture point
  Eigen::Vector2d planned_zmp = Eigen::Vector2d::Zero();        // m, from the stance ankle
  Eigen::Vector2d ankle_offset = Eigen::Vector2d::Zero();       // rad: stance pitch, roll
  double hat_angle = 0;                                         // rad, trunk forward
  int steps_moved = 0;                                          // landings moved so far
  Eigen::Vector2d walk_offset = Eigen::Vector2d::Zero();        // m, the walk moved in all
  double first_detection = -1;                                  // s, first frame not none
  double gait_phase = 0;                                        // 0..1 of the stride

  static constexpr std::string_view kTypeName = "PushRecoveryState";
  static constexpr auto fields() {
    using S = PushRecoveryState;
    return std::make_tuple(
        field("sagittal", &S::sagittal), field("lateral", &S::lateral),
        field("deviation", &S::deviation, "m"), field("deviation_rate", &S::deviation_rate, "m/s"),
        field("capture_deviation", &S::capture_deviation, "m"),
        field("planned_zmp", &S::planned_zmp, "m"), field("ankle_offset", &S::ankle_offset, "rad"),
        field("hat_angle", &S::hat_angle, "rad"), field("steps_moved", &S::steps_moved),
        field("walk_offset", &S::walk_offset, "m"),
        field("first_detection", &S::first_detection, "s"), field("gait_phase", &S::gait_phase));
  }
};

}  // namespace stride

namespace stride::behaviours {

struct PushRecoveryParameters {
  bool enabled = true;  // false: the plain pattern, PatternWalk's targets exactly
  // m of capture-point deviation that is the walk's own (the unpushed medium walk on the 3 mm
  // floor reaches -0.061..0.025 m forward and -0.069..0.054 m sideways)
  double threshold = 0.07;
  double lateral_threshold = 0.08;
  bool hip = true;  // sagittal hip and combined responses allowed
  // m of capture-point deviation beyond which the stance ankle acts (per axis); the thresholds
  // above gate the hip, combined and step responses only. Sagittally the ankle acts from 2 cm,
  // before a push is classified (at 7 cm, the first measurement, it came too late: README);
  // sideways from the lateral threshold (acting on the walk's own +-5 cm sway lost more walks).
  double ankle_threshold = 0.02, ankle_lateral_threshold = 0.08;
  double ankle_pitch_gain = 1.5;  // rad per m of capture-point deviation beyond the threshold
  double ankle_roll_gain = 1.5;
  double max_ankle = 0.12;  // rad
  double tau_forward = 14;  // N m, both hips together (HipBalance's)
  double tau_backward = -14;
  double max_hat = 0.35;  // rad
  double hat_hold_time = 0.15;
  double hat_return_time = 0.4;
  double step_gain = 1.0;
  double max_forward = 0.04, max_backward = 0.03, max_outward = 0.04, max_inward = 0.01;  // m
  double min_swing_time = 0.06;   // s a swing must have left to be moved
  double step_tolerance = 0.008;  // m: smaller moves of a landing are not made
  double lower = 0.015;           // m the waist is lowered for a recovery step
  double lower_hold = 0.5;        // s
  double lower_return = 0.5;      // s
  double com_offset_time = 0.5;   // s before the walk over which the CoM-waist offset is learned

  StepLimits limits() const { return {max_forward, max_backward, max_outward, max_inward}; }

  static constexpr std::string_view kTypeName = "PushRecoveryParameters";
  static constexpr auto fields() {
    using P = PushRecoveryParameters;
    return std::make_tuple(
        field("enabled", &P::enabled), field("threshold", &P::threshold, "m", Range{0, 0.5}),
        field("lateral_threshold", &P::lateral_threshold, "m", Range{0, 0.5}),
        field("hip", &P::hip), field("ankle_threshold", &P::ankle_threshold, "m", Range{0, 0.5}),
        field("ankle_lateral_threshold", &P::ankle_lateral_threshold, "m", Range{0, 0.5}),
        field("ankle_pitch_gain", &P::ankle_pitch_gain, "rad/m", Range{0, 20}),
        field("ankle_roll_gain", &P::ankle_roll_gain, "rad/m", Range{0, 20}),
        field("max_ankle", &P::max_ankle, "rad", Range{0, 0.5}),
        field("tau_forward", &P::tau_forward, "N*m", Range{0.01, 100}),
        field("tau_backward", &P::tau_backward, "N*m", Range{-100, -0.01}),
        field("max_hat", &P::max_hat, "rad", Range{0, 1}),
        field("hat_hold_time", &P::hat_hold_time, "s", Range{0, 5}),
        field("hat_return_time", &P::hat_return_time, "s", Range{0.01, 5}),
        field("step_gain", &P::step_gain, "", Range{0, 3}),
        field("max_forward", &P::max_forward, "m", Range{0, 0.15}),
        field("max_backward", &P::max_backward, "m", Range{0, 0.15}),
        field("max_outward", &P::max_outward, "m", Range{0, 0.15}),
        field("max_inward", &P::max_inward, "m", Range{0, 0.1}),
        field("min_swing_time", &P::min_swing_time, "s", Range{0, 1}),
        field("step_tolerance", &P::step_tolerance, "m", Range{0, 0.1}),
        field("lower", &P::lower, "m", Range{0, 0.06}),
        field("lower_hold", &P::lower_hold, "s", Range{0, 10}),
        field("lower_return", &P::lower_return, "s", Range{0.01, 10}),
        field("com_offset_time", &P::com_offset_time, "s", Range{0.01, 10}));
  }
};

// The walk (PatternWalk's parameters) and the recovery, as `walk.<field>` and `recovery.<field>`.
struct PushRecoveryWalkParameters {
  WalkParameters walk;
  PushRecoveryParameters recovery;

  static constexpr std::string_view kTypeName = "PushRecoveryWalkParameters";
  static constexpr auto fields() {
    using P = PushRecoveryWalkParameters;
    return std::make_tuple(field("walk", &P::walk), field("recovery", &P::recovery));
  }
};

void register_push_recovery_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
