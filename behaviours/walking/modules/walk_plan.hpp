#pragma once
// What the walking pattern plans, for viewers and logs: the ZMP reference now and the next
// footsteps. Frame: the pattern's walk frame (walking_pattern.hpp: ground, origin midway between
// the feet where the walk started, x forward, y left); poses are sole-frame origins x, y, yaw.
#include <array>
#include <cstdint>

#include "behaviours/walking/pattern/adjusted_pattern.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "robot/framework/reflect.hpp"

namespace stride {

inline constexpr int kWalkPlanSteps = 4;

struct WalkPlan {
  STRIDE_FIELDS(WalkPlan);
  // pattern time sampled (clamped to the walk)
  STRIDE_FIELD(double, t, "s") = 0.0;
  // the ZMP reference of Eq. 3.16
  STRIDE_FIELD((std::array<double, 2>), zmp, "m"){};
  // 0 both feet, 1 left foot, 2 right foot
  STRIDE_FIELD(std::int64_t, support) = 0;
  // planned now (x, y, yaw)
  STRIDE_FIELD((std::array<double, 3>), left_foot){};
  STRIDE_FIELD((std::array<double, 3>), right_foot){};
  STRIDE_FIELD(std::int64_t, steps) = 0;  // footsteps ahead listed below (at most kWalkPlanSteps)
  STRIDE_FIELD((std::array<double, kWalkPlanSteps>), step_x, "m"){};
  STRIDE_FIELD((std::array<double, kWalkPlanSteps>), step_y, "m"){};
  STRIDE_FIELD((std::array<double, kWalkPlanSteps>), step_yaw, "rad"){};
  // the landing foot: 1 left, 2 right
  STRIDE_FIELD((std::array<std::int64_t, kWalkPlanSteps>), step_foot){};

  static constexpr std::string_view kTypeName = "WalkPlan";
};

namespace walking {
// The plan at pattern time `t` (already clamped to [0, duration]) from its sample there: the
// landings of the swings not yet ended, soonest first.
WalkPlan walk_plan(const PatternSample& sample, const Footsteps& feet, double t);
// The same for a walk re-planned on the way: its landings as the moved steps now have them.
WalkPlan walk_plan(const PatternSample& sample, const AdjustedPattern& pattern, double t);
}  // namespace walking

}  // namespace stride
