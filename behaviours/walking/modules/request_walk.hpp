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
  static constexpr double kFromPreset = std::numeric_limits<double>::quiet_NaN();

  WalkPreset preset = WalkPreset::medium;
  double T_stride = kFromPreset;  // s; "nan": the preset's (as WalkParameters)
  double tau_dsp = kFromPreset;   // double-support ratio
  double A_l = kFromPreset;       // m
  double z_min = kFromPreset;     // m
  double z_max = kFromPreset;     // m
  double d_0 = kFromPreset;       // m
  double H_foot = kFromPreset;    // m
  // walking::StepLimits, field by field (the defaults are its defaults).
  double max_forward = walking::StepLimits{}.max_forward;              // m/s
  double max_backward = walking::StepLimits{}.max_backward;            // m/s
  double max_sideways = walking::StepLimits{}.max_sideways;            // m/s
  double max_turn = walking::StepLimits{}.max_turn;                    // rad/s
  double forward_per_step = walking::StepLimits{}.forward_per_step;    // m/s a step
  double sideways_per_step = walking::StepLimits{}.sideways_per_step;  // m/s a step
  double turn_per_step = walking::StepLimits{}.turn_per_step;          // rad/s a step
  // Share of its swing within which a foot steps sideways and turns
  // (walking/steps/online_walk.hpp).
  double early_share = walking::OnlineWalk::kEarlyShare;
  // Heading loop: turn rate added (rad/s per rad) to steps planned while the torso's measured
  // yaw (WalkOdometry) lags the granted requests' (feet turn on the floor); at most max_turn more.
  double heading_gain = 0.0;
  // Place loop: forward and sideways speed added (m/s per m) to steps planned while the torso's
  // measured place (WalkOdometry) is behind the granted requests' path; within the limits.
  double place_gain = 0.0;
  double start_delay = 1.0;         // s standing before the first step may start
  double interpolation_time = 1.0;  // s from the measured pose to the standing pose

  static constexpr std::string_view kTypeName = "RequestWalkParameters";
  static constexpr auto fields() {
    using P = RequestWalkParameters;
    return std::make_tuple(
        field("preset", &P::preset), field("T_stride", &P::T_stride, "s"),
        field("tau_dsp", &P::tau_dsp), field("A_l", &P::A_l, "m"), field("z_min", &P::z_min, "m"),
        field("z_max", &P::z_max, "m"), field("d_0", &P::d_0, "m"),
        field("H_foot", &P::H_foot, "m"), field("max_forward", &P::max_forward, "m/s", Range{0, 1}),
        field("max_backward", &P::max_backward, "m/s", Range{0, 1}),
        field("max_sideways", &P::max_sideways, "m/s", Range{0, 1}),
        field("max_turn", &P::max_turn, "rad/s", Range{0, 5}),
        field("forward_per_step", &P::forward_per_step, "m/s", Range{0.001, 1}),
        field("sideways_per_step", &P::sideways_per_step, "m/s", Range{0.001, 1}),
        field("turn_per_step", &P::turn_per_step, "rad/s", Range{0.001, 5}),
        field("early_share", &P::early_share, "", Range{0.1, 1}),
        field("heading_gain", &P::heading_gain, "1/s", Range{0, 20}),
        field("place_gain", &P::place_gain, "1/s", Range{0, 20}),
        field("start_delay", &P::start_delay, "s", Range{0, 3600}),
        field("interpolation_time", &P::interpolation_time, "s", Range{0, 3600}));
  }
};

// The walk's pattern parameters: the preset with the set fields replacing its values; throws
// stride::Error naming the parameter that makes them unusable.
walking::PatternParameters request_walk_pattern(const RequestWalkParameters& p);
walking::StepLimits request_walk_limits(const RequestWalkParameters& p);

void register_request_walk_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
