#pragma once
// The simulated torso's world pose at a frame's sensor time: what a simulation's log records
// beside the blackboard's representations (not on the blackboard: no module reads it, so logging
// cannot change a run), so that `log goto` shows where the robot stood. Logs of a physical robot,
// and logs recorded before kWorldPoseSince, hold none.
#include <string_view>

#include "robot/framework/reflect.hpp"

namespace stride {

struct SimulatedTorsoPose {
  double x = 0, y = 0, z = 0;           // m, world frame
  double roll = 0, pitch = 0, yaw = 0;  // rad, Z-Y-X

  static constexpr std::string_view kTypeName = "SimulatedTorsoPose";
  static constexpr auto fields() {
    return std::make_tuple(
        field("x", &SimulatedTorsoPose::x, "m"), field("y", &SimulatedTorsoPose::y, "m"),
        field("z", &SimulatedTorsoPose::z, "m"), field("roll", &SimulatedTorsoPose::roll, "rad"),
        field("pitch", &SimulatedTorsoPose::pitch, "rad"),
        field("yaw", &SimulatedTorsoPose::yaw, "rad"));
  }
};

// The first day simulation logs carry a SimulatedTorsoPose.
inline constexpr std::string_view kWorldPoseSince = "2026-12-06";

}  // namespace stride
