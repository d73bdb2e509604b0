#pragma once
// Walking on request: RequestWalk plays the thesis' Ch. 3 pattern planned online step by step
// (walking/steps/online_walk.hpp) from the WalkRequest, and provides the WalkingJointRequest (leg
// IK of the planned waist and feet, like PatternWalk's), the WalkPlan and the WalkStatus.
// ScriptedWalkRequest provides the WalkRequest from its parameters.
//
// Changes while walking: the limits take effect at the next step planned; pattern parameters
// (preset, T_stride, ...) wait until the robot stands again (WalkStatus.parameters_pending), as
// the pattern's height and sway cannot jump mid-walk. A bad value keeps the old set and says why.
#include <limits>
#include <string_view>

#include "behaviours/walking/modules/walk_parameters.hpp"
#include "behaviours/walking/steps/online_walk.hpp"
#include "behaviours/walking/steps/step_velocity.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"

namespace stride::behaviours {

struct RequestWalkParameters {
  STRIDE_FIELDS(RequestWalkParameters);
  static constexpr double kFromPreset = std::numeric_limits<double>::quiet_NaN();

  STRIDE_FIELD(WalkPreset, preset) = WalkPreset::medium;
  STRIDE_FIELD(double, T_stride, "s") = kFromPreset;  // s; "nan": the preset's (as WalkParameters)
  STRIDE_FIELD(double, tau_dsp) = kFromPreset;        // double-support ratio
  STRIDE_FIELD(double, A_l, "m") = kFromPreset;
  STRIDE_FIELD(double, z_min, "m") = kFromPreset;
  STRIDE_FIELD(double, z_max, "m") = kFromPreset;
  STRIDE_FIELD(double, d_0, "m") = kFromPreset;
  STRIDE_FIELD(double, H_foot, "m") = kFromPreset;
  // walking::StepLimits, field by field (the defaults are its defaults).
  STRIDE_FIELD(double, max_forward, "m/s", Range{0, 1}) = walking::StepLimits{}.max_forward;
  STRIDE_FIELD(double, max_backward, "m/s", Range{0, 1}) = walking::StepLimits{}.max_backward;
  STRIDE_FIELD(double, max_sideways, "m/s", Range{0, 1}) = walking::StepLimits{}.max_sideways;
  STRIDE_FIELD(double, max_turn, "rad/s", Range{0, 5}) = walking::StepLimits{}.max_turn;
  // m/s a step
  STRIDE_FIELD(double, forward_per_step, "m/s",
               Range{0.001, 1}) = walking::StepLimits{}.forward_per_step;
  // m/s a step
  STRIDE_FIELD(double, sideways_per_step, "m/s",
               Range{0.001, 1}) = walking::StepLimits{}.sideways_per_step;
  // rad/s a step
  STRIDE_FIELD(double, turn_per_step, "rad/s",
               Range{0.001, 5}) = walking::StepLimits{}.turn_per_step;
  // Share of its swing within which a foot steps sideways and turns
  // (walking/steps/online_walk.hpp).
  STRIDE_FIELD(double, early_share, "", Range{0.1, 1}) = walking::OnlineWalk::kEarlyShare;
  // Heading loop: turn rate added (rad/s per rad) to steps planned while the torso's measured
  // yaw (WalkOdometry) lags the granted requests' (feet turn on the floor); at most max_turn more.
  STRIDE_FIELD(double, heading_gain, "1/s", Range{0, 20}) = 0.0;
  // Place loop: forward and sideways speed added (m/s per m) to steps planned while the torso's
  // measured place (WalkOdometry) is behind the granted requests' path; within the limits.
  STRIDE_FIELD(double, place_gain, "1/s", Range{0, 20}) = 0.0;
  // s standing before the first step may start
  STRIDE_FIELD(double, start_delay, "s", Range{0, 3600}) = 1.0;
  // s from the measured pose to the standing pose
  STRIDE_FIELD(double, interpolation_time, "s", Range{0, 3600}) = 1.0;

  static constexpr std::string_view kTypeName = "RequestWalkParameters";
};

// The walk's pattern parameters: the preset with the set fields replacing its values; throws
// stride::Error naming the parameter that makes them unusable.
walking::PatternParameters request_walk_pattern(const RequestWalkParameters& p);
walking::StepLimits request_walk_limits(const RequestWalkParameters& p);

void register_request_walk_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
