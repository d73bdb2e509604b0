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
  STRIDE_FIELDS(WalkRequest);
  STRIDE_FIELD(WalkMode, mode) = WalkMode::stand;
  STRIDE_FIELD(double, forward, "m/s") = 0.0;       // m/s, x of the torso
  STRIDE_FIELD(double, sideways, "m/s") = 0.0;      // m/s, left positive
  STRIDE_FIELD(double, turn, "rad/s") = 0.0;        // rad/s, counter-clockwise positive
  STRIDE_FIELD((std::array<double, 3>), target){};  // x, y (m), yaw (rad)

  static constexpr std::string_view kTypeName = "WalkRequest";
};

// ScriptedWalkRequest's parameters: the request it provides (scenes change them with <at>).
struct ScriptedWalkRequestParameters {
  STRIDE_FIELDS(ScriptedWalkRequestParameters);
  STRIDE_FIELD(WalkMode, mode) = WalkMode::stand;
  STRIDE_FIELD(double, forward, "m/s", Range{-1, 1}) = 0.0;
  STRIDE_FIELD(double, sideways, "m/s", Range{-1, 1}) = 0.0;
  STRIDE_FIELD(double, turn, "rad/s", Range{-5, 5}) = 0.0;
  STRIDE_FIELD((std::array<double, 3>), target, "", Range{-1000, 1000}){};

  static constexpr std::string_view kTypeName = "ScriptedWalkRequestParameters";
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
  STRIDE_FIELDS(WalkStatus);
  STRIDE_FIELD(WalkState, state) = WalkState::standing;
  STRIDE_FIELD(double, granted_forward, "m/s") = 0.0;
  STRIDE_FIELD(double, granted_sideways, "m/s") = 0.0;
  STRIDE_FIELD(double, granted_turn, "rad/s") = 0.0;
  // the request is beyond the walk's range (clamped)
  STRIDE_FIELD(bool, limited) = false;
  // the granted velocity is still on its way to the request
  STRIDE_FIELD(bool, ramping) = false;
  // waist step under way (-1 standing), counted per walk
  STRIDE_FIELD(std::int64_t, step) = -1;
  STRIDE_FIELD(std::int64_t, steps) = 0;  // waist steps planned since the module started
  // x, y (m) and yaw (rad) of the granted requests' path
  STRIDE_FIELD((std::array<double, 3>), odometry){};
  STRIDE_FIELD((std::array<double, 3>), plan){};  // x, y, yaw of the walk frame as planned
  // rad: the gyro's z rate integrated since the start
  STRIDE_FIELD(double, measured_yaw, "rad") = 0.0;
  STRIDE_FIELD(std::int64_t, ik_beyond_limit_frames) = 0;
  // plans halved to keep the leg IK within the limits
  STRIDE_FIELD(std::int64_t, shortened_steps) = 0;
  // changed pattern parameters wait for the next stand
  STRIDE_FIELD(bool, parameters_pending) = false;

  static constexpr std::string_view kTypeName = "WalkStatus";
};

}  // namespace stride
