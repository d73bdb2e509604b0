#pragma once
// The simulated torso's world pose at a frame's sensor time: what a simulation's log records
// beside the blackboard's representations (not on the blackboard: no module reads it, so logging
// cannot change a run), so that `log goto` shows where the robot stood. Logs of a physical robot,
// and logs recorded before kWorldPoseSince, hold none.
#include <string_view>

#include "robot/framework/reflect.hpp"

namespace stride {

struct SimulatedTorsoPose {
  STRIDE_FIELDS(SimulatedTorsoPose);
  // m, world frame
  STRIDE_FIELD(double, x, "m") = 0;
  STRIDE_FIELD(double, y, "m") = 0;
  STRIDE_FIELD(double, z, "m") = 0;
  // rad, Z-Y-X
  STRIDE_FIELD(double, roll, "rad") = 0;
  STRIDE_FIELD(double, pitch, "rad") = 0;
  STRIDE_FIELD(double, yaw, "rad") = 0;

  static constexpr std::string_view kTypeName = "SimulatedTorsoPose";
};

// The first day simulation logs carry a SimulatedTorsoPose.
inline constexpr std::string_view kWorldPoseSince = "2026-12-06";

}  // namespace stride
