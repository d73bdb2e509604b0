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
  double t = 0.0;                                   // pattern time sampled (clamped to the walk)
  std::array<double, 2> zmp{};                      // the ZMP reference of Eq. 3.16
  std::int64_t support = 0;                         // 0 both feet, 1 left foot, 2 right foot
  std::array<double, 3> left_foot{}, right_foot{};  // planned now (x, y, yaw)
  std::int64_t steps = 0;  // footsteps ahead listed below (at most kWalkPlanSteps)
  std::array<double, kWalkPlanSteps> step_x{}, step_y{}, step_yaw{};
  std::array<std::int64_t, kWalkPlanSteps> step_foot{};  // the landing foot: 1 left, 2 right

  static constexpr std::string_view kTypeName = "WalkPlan";
  static constexpr auto fields() {
    using W = WalkPlan;
    return std::make_tuple(field("t", &W::t, "s"), field("zmp", &W::zmp, "m"),
                           field("support", &W::support), field("left_foot", &W::left_foot),
                           field("right_foot", &W::right_foot), field("steps", &W::steps),
                           field("step_x", &W::step_x, "m"), field("step_y", &W::step_y, "m"),
                           field("step_yaw", &W::step_yaw, "rad"),
                           field("step_foot", &W::step_foot));
  }
};

namespace walking {
// The plan at pattern time `t` (already clamped to [0, duration]) from its sample there: the
// landings of the swings not yet ended, soonest first.
WalkPlan walk_plan(const PatternSample& sample, const Footsteps& feet, double t);
// The same for a walk re-planned on the way: its landings as the moved steps now have them.
WalkPlan walk_plan(const PatternSample& sample, const AdjustedPattern& pattern, double t);
}  // namespace walking

}  // namespace stride
