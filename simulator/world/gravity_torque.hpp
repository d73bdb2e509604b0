#pragma once
// The torque gravity exerts about a joint's axis through the given links: what the joint's motor
// must hold when the robot is still (used to check simulated currents against statics).
#include <initializer_list>
#include <string>

#include "simulator/world/robot_body.hpp"

namespace stride::sim {

// Signed, about the joint axis in the world frame; links by name, each must exist.
double gravity_torque_about_joint(const RobotBody& body, const std::string& joint,
                                  std::initializer_list<const char*> links, double gravity = 9.81);

}  // namespace stride::sim
