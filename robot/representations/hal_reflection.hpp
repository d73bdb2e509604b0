#pragma once
// Field lists for the robot/hal structs, so the raw link data is a representation like any other.
#include "robot/framework/reflect.hpp"
#include "robot/hal/actuator_frame.hpp"
#include "robot/hal/sensor_frame.hpp"

namespace stride {

template <>
struct EnumNames<hal::ServoMode> {
  static constexpr std::string_view type_name = "ServoMode";
  static constexpr std::array<std::string_view, 2> names{"Position", "Torque"};
};

template <>
struct Reflect<hal::SensorFrame> {
  using S = hal::SensorFrame;
  static constexpr std::string_view type_name() { return "SensorFrame"; }
  static constexpr auto fields() {
    return std::make_tuple(field("time", &S::time, "s"),
                           field("position", &S::position, "rad").named(hal::kJointNames),
                           field("stiffness", &S::stiffness).named(hal::kJointNames),
                           field("current", &S::current, "A").named(hal::kJointNames),
                           field("temperature", &S::temperature, "degC").named(hal::kJointNames),
                           field("accelerometer", &S::accelerometer, "m/s^2"),
                           field("gyroscope", &S::gyroscope, "rad/s"),
                           field("angles", &S::angles, "rad"), field("fsr", &S::fsr, "N"),
                           field("battery", &S::battery), field("sonar", &S::sonar, "m"),
                           field("status", &S::status), field("touch", &S::touch),
                           field("robot_config", &S::robot_config));
  }
};

template <>
struct Reflect<hal::ActuatorFrame> {
  using A = hal::ActuatorFrame;
  static constexpr std::string_view type_name() { return "ActuatorFrame"; }
  static constexpr auto fields() {
    return std::make_tuple(
        field("mode", &A::mode).named(hal::kJointNames),
        field("position", &A::position, "rad").named(hal::kJointNames),
        field("stiffness", &A::stiffness, "", Range{0, 1}).named(hal::kJointNames),
        field("torque", &A::torque, "N*m").named(hal::kJointNames));
  }
};

}  // namespace stride
