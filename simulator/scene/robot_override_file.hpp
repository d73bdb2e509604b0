#pragma once
// <include file="robot-id.xml"/> inside a scene's <robot>: a <robot_override> file (what `stride
// identify` writes) whose <motor>, <servo>, <calibration> and <imu> children the scene parser
// reads as if they were written in the <robot>.
#include <memory>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "robot/core/xml_element.hpp"

namespace stride::sim {

// Keeps the files' documents and names alive while the elements read from them are in use.
struct RobotOverrideFiles {
  std::vector<std::unique_ptr<tinyxml2::XMLDocument>> docs;
  std::vector<std::unique_ptr<std::string>> paths;
};

// The included file's children, checked to be motor, servo, calibration or imu elements; fails
// at the <include> for an unreadable file, at the file's line for bad XML or a wrong root.
std::vector<XmlElement> robot_override_children(const XmlElement& include,
                                                RobotOverrideFiles& files);

}  // namespace stride::sim
