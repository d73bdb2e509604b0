#pragma once
// Reading <motor>, <servo> and <calibration> overrides that a scene writes inside <robot> (the
// device file itself is read by load_device_file, declared with the description).
#include "robot/core/xml_element.hpp"
#include "simulator/scene/device_description.hpp"

namespace stride::sim {

// Checks the attributes (units, > 0) where they are written; fails through XmlElement.
MotorOverride motor_override(const XmlElement& e);
ServoOverride servo_override(const XmlElement& e);
// sd in (0, 10deg]; joint names (space or comma separated) listed once.
CalibrationSpread calibration_spread(const XmlElement& e);
// <imu gyro_bias="x y z"/>: the gyro's bias (rad/s per torso axis) over the device file's.
Eigen::Vector3d gyro_bias_override(const XmlElement& e);

}  // namespace stride::sim
