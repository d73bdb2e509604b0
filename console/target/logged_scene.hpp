#pragma once
// A log frame as a scene to draw: the live scene with robot `robot` placed as the frame shows it
// (its logged joint angles; its torso where the simulation's log recorded it, or for a log
// without a world pose, a physical robot's, tilted as its IMU measured with its lowest point on
// the ground at the origin, as the view draws one). Nothing moves in it: `snapshot` renders it.
#include <optional>

#include "robot/representations/inertial_sensor_data.hpp"
#include "robot/representations/joint_sensor_data.hpp"
#include "robot/runtime/world_pose.hpp"
#include "simulator/scene/scene_description.hpp"
#include "simulator/simulated_robot.hpp"

namespace stride::console {

sim::SceneDescription logged_scene(const sim::SceneDescription& live, int robot,
                                   const model::RobotModel& model, const JointSensorData& joints,
                                   const InertialSensorData& imu,
                                   const std::optional<SimulatedTorsoPose>& pose);

}  // namespace stride::console
