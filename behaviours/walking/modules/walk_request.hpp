#pragma once
// What a team asks of the walk (WalkRequest) and what the walk does about it (WalkStatus).
// RequestWalk (request_walk.hpp) reads the one and provides the other; ScriptedWalkRequest
// provides the request from its parameters, so scenes schedule requests with <at> and the console
// sets them (`set module:ScriptedWalkRequest ...` or `set representation:WalkRequest ...`).
#include <array>
#include <cstdint>
#include <string_view>

#include "robot/framework/reflect.hpp"

namespace stride {

enum class WalkMode { stand, walk, target };

template <>
struct EnumNames<WalkMode> {
  static constexpr std::string_view type_name = "WalkMode";
  static constexpr std::array<std::string_view, 3> names{"stand", "walk", "target"};
};

// walk: speeds of the torso in its own axes; target: walk to a pose of the odometry's frame
// (WalkStatus.odometry) and stand there; stand brings the walk to a stop at the next chance.
struct WalkRequest {
  WalkMode mode = WalkMode::stand;
  double forward = 0.0;            // m/s, x of the torso
  double sideways = 0.0;           // m/s, left positive
  double turn = 0.0;               // rad/s, counter-clockwise positive
  std::array<double, 3> target{};  // x, y (m), yaw (rad)

  static constexpr std::string_view kTypeName = "WalkRequest";
  static constexpr auto fields() {
    using W = WalkRequest;
    return std::make_tuple(field("mode", &W::mode), field("forward", &W::forward, "m/s"),
                           field("sideways", &W::sideways, "m/s"), field("turn", &W::turn, "rad/s"),
                           field("target", &W::target));
  }
};

// ScriptedWalkRequest's parameters: the request it provides (scenes change them with <at>).
struct ScriptedWalkRequestParameters {
  WalkMode mode = WalkMode::stand;
  double forward = 0.0;   // m/s
  double sideways = 0.0;  // m/s
  double turn = 0.0;      // rad/s
  std::array<double, 3> target{};

  static constexpr std::string_view kTypeName = "ScriptedWalkRequestParameters";
  static constexpr auto fields() {
    using W = ScriptedWalkRequestParameters;
    return std::make_tuple(field("mode", &W::mode),
                           field("forward", &W::forward, "m/s", Range{-1, 1}),
                           field("sideways", &W::sideways, "m/s", Range{-1, 1}),
                           field("turn", &W::turn, "rad/s", Range{-5, 5}),
                           field("target", &W::target, "", Range{-1000, 1000}));
  }
};

enum class WalkState { standing, walking, stopping };

template <>
struct EnumNames<WalkState> {
  static constexpr std::string_view type_name = "WalkState";
  static constexpr std::array<std::string_view, 3> names{"standing", "walking", "stopping"};
};

// The walk's answer: what it granted for the step last planned (the request within the walk's
// range and its change per step), whether that is less than asked, where the granted requests
// put the torso's walk frame (odometry: their integral, from where the module started), where the
// plan has it (with the heading loop's turns) and the torso's yaw the gyro says.
struct WalkStatus {
  WalkState state = WalkState::standing;
  double granted_forward = 0.0;      // m/s
  double granted_sideways = 0.0;     // m/s
  double granted_turn = 0.0;         // rad/s
  bool limited = false;              // the request is beyond the walk's range (clamped)
  bool ramping = false;              // the granted velocity is still on its way to the request
  std::int64_t step = -1;            // waist step under way (-1 standing), counted per walk
  std::int64_t steps = 0;            // waist steps planned since the module started
  std::array<double, 3> odometry{};  // x, y (m) and yaw (rad) of the granted requests' path
  std::array<double, 3> plan{};      // x, y, yaw of the walk frame as planned
  double measured_yaw = 0.0;         // rad: the gyro's z rate integrated since the start
  std::int64_t ik_beyond_limit_frames = 0;
  std::int64_t shortened_steps = 0;  // plans halved to keep the leg IK within the limits
  bool parameters_pending = false;   // changed pattern parameters wait for the next stand

  static constexpr std::string_view kTypeName = "WalkStatus";
  static constexpr auto fields() {
    using W = WalkStatus;
    return std::make_tuple(
        field("state", &W::state), field("granted_forward", &W::granted_forward, "m/s"),
        field("granted_sideways", &W::granted_sideways, "m/s"),
        field("granted_turn", &W::granted_turn, "rad/s"), field("limited", &W::limited),
        field("ramping", &W::ramping), field("step", &W::step), field("steps", &W::steps),
        field("odometry", &W::odometry), field("plan", &W::plan),
        field("measured_yaw", &W::measured_yaw, "rad"),
        field("ik_beyond_limit_frames", &W::ik_beyond_limit_frames),
        field("shortened_steps", &W::shortened_steps),
        field("parameters_pending", &W::parameters_pending));
  }
};

}  // namespace stride
