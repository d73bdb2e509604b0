#pragma once
// A robot seen only through its sensors (a physical robot, a log): its links placed from joint
// angles and the IMU's torso roll and pitch, with the lower foot standing on the ground at the
// origin (a robot has no true world pose; yaw and position are unknown and drawn as zero, until a
// walk's plan places it: stand_on_plan in walk_plan_overlay.hpp).
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "console/view/robot_frame.hpp"
#include "robot/model/robot_model.hpp"

namespace stride::view {

// "[HeadYaw=0.1, HeadPitch=-0.2]" (how `get` prints a named array) -> {HeadYaw: 0.1, ...};
// elements that are not numbers are left out.
std::map<std::string, double> named_numbers(std::string_view text);
// "[0.01, -0.02]" -> {0.01, -0.02}; nothing if any element is not a number.
std::vector<double> numbers(std::string_view text);
// ["A", "B"] -> {A, B} (names without commas or quotes inside).
std::vector<std::string> strings(std::string_view text);

// A robot whose torso's world pose is known (a simulation's log): its links placed from there.
RobotFrame posed_robot_frame(const model::RobotModel& model, const std::string& name,
                             const std::map<std::string, double>& joints,
                             const Eigen::Isometry3d& torso);

RobotFrame kinematic_robot_frame(const model::RobotModel& model, const std::string& name,
                                 const std::map<std::string, double>& joints, double roll,
                                 double pitch);

}  // namespace stride::view
