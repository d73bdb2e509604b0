#pragma once
// One robot's part of a `frame` message (PROTOCOL.md): link poses in the scene's link order,
// centre of mass, ZMP reference, measured centre of pressure, support polygon, contacts, planned
// footsteps and whether it fell. Unknown quantities stay empty and go out as null.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "console/view/view_json.hpp"

namespace stride::sim {
class Simulation;
}

namespace stride::view {

struct RobotFrame {
  std::string name;
  std::vector<Eigen::Isometry3d> links;
  std::optional<Eigen::Vector3d> com;
  std::optional<Eigen::Vector2d> zmp_ref, cop;
  std::vector<Eigen::Vector2d> support;                               // convex, counter-clockwise
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> contacts;  // point, force on the robot
  struct Footstep {
    Eigen::Vector3d pose;  // x, y, yaw
    bool left = false;
  };
  std::vector<Footstep> footsteps;            // planned, world frame (walk_plan_overlay.hpp)
  std::optional<Eigen::Vector3d> walk_frame;  // the plan's walk frame in the world: x, y, yaw
  bool fell = false;
};

Json robot_frame_json(const RobotFrame& f);

// Robot `i` of a simulation as the physics world has it (true poses and contact forces).
RobotFrame simulated_robot_frame(const sim::Simulation& simulation, int i);

// The convex hull of `points` (counter-clockwise, no repeated points).
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points);

}  // namespace stride::view
