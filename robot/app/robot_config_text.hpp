#pragma once
// A RobotConfig written back as the XML `stride robot --config` reads: how a sweep run through
// LoLA hands its controller (the scene's, with the run's settings) to a started robot process.
#include <string>

#include "robot/app/robot_config.hpp"

namespace stride {

// The config as <robot_config> text; parse_robot_config_text() of it gives `config` back (the
// urdf should be absolute: the text is read from wherever it is written). Times to the bit.
std::string robot_config_xml(const RobotConfig& config);

}  // namespace stride
