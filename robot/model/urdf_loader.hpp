#pragma once
// URDF -> RobotModel through urdfdom. Any URDF whose collisions are boxes, cylinders and spheres.
#include <string>

#include "robot/model/robot_model.hpp"

namespace stride::model {

// Throws stride::Error with "file:line: what was expected" on any problem; never returns a
// partial model. A relative path not found from the working directory is looked up in the data
// directory (robot/core/data_dir.hpp).
RobotModel load_urdf(const std::string& path);
RobotModel parse_urdf(const std::string& xml, const std::string& source_name);

}  // namespace stride::model
