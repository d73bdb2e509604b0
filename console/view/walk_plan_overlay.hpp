#pragma once
// The walking pattern's plan (representation WalkPlan, in its walk frame) placed in the world the
// view draws: the walk frame is anchored so that the planned support foot (both feet: their
// midpoint) lies on the drawn one, so the ZMP reference and footsteps follow the robot as it is.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "console/view/robot_frame.hpp"
#include "robot/model/robot_model.hpp"

namespace stride::view {

struct WalkPlanValues {
  std::array<double, 2> zmp{};
  int support = 0;  // 0 both feet, 1 left, 2 right
  std::array<double, 3> left{}, right{};
  std::vector<std::array<double, 4>> steps;  // x, y, yaw, foot (1 left, 2 right)
};

inline constexpr const char* kWalkPlanKey = "representation:WalkPlan";  // one key: one request

// The plan from what `get representation:WalkPlan` prints; nullopt when a field is missing or
// not what it should be, or the plan was never written.
std::optional<WalkPlanValues> read_walk_plan(std::string_view printed);

// Moves a robot drawn from its sensors alone (kinematic_frame.hpp) so that its drawn support lies
// where the plan puts it: a robot with no world pose walks across the view along its own plan
// (the planned path, not the true one, which its slip and falls can leave).
void stand_on_plan(RobotFrame& f, const model::RobotModel& model, const WalkPlanValues& plan);

// Sets f.zmp_ref, f.footsteps and f.walk_frame from `plan`; `model` names f.links (LFoot, RFoot).
void place_walk_plan(RobotFrame& f, const model::RobotModel& model, const WalkPlanValues& plan);

}  // namespace stride::view
