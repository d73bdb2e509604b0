#pragma once
// Reading <motor>, <servo> and <calibration> overrides that a scene writes inside <robot> (the
// device file itself is read by load_device_file, declared with the description).
#include "simulator/devices/device_description.hpp"
#include "robot/core/xml_element.hpp"

namespace stride::sim {

// Checks the attributes (units, > 0) where they are written; fails through XmlElement.
MotorOverride motor_override(const XmlElement& e);
ServoOverride servo_override(const XmlElement& e);
// sd in (0, 10deg]; joint names (space or comma separated) listed once.
CalibrationSpread calibration_spread(const XmlElement& e);

}  // namespace stride::sim
