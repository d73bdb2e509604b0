#pragma once
// What a hardware link delivers each control frame: raw device readings in SI units, LoLA order.
#include <array>
#include <cstdint>
#include <string>

#include "robot/hal/joint_id.hpp"

namespace stride::hal {

struct SensorFrame {
  double time = 0;                               // s, link clock at sampling
  std::array<double, kNumJoints> position{};     // rad (hands: open fraction)
  std::array<double, kNumJoints> stiffness{};    // 0..1, as currently applied
  std::array<double, kNumJoints> current{};      // A, motor armature current
  std::array<double, kNumJoints> temperature{};  // deg C
  std::array<double, 3> accelerometer{};         // m/s^2, torso frame, +z up when standing
  std::array<double, 3> gyroscope{};             // rad/s, torso frame
  std::array<double, 2> angles{};                // rad, torso roll and pitch from the IMU's filter
  std::array<double, kNumFsr> fsr{};             // N, LoLA FSR order
  std::array<double, 4> battery{1.0, 0.0, 0.0, 30.0};  // charge, status, current, temperature
  std::array<double, 2> sonar{};                       // m, left and right (not simulated)
  std::array<std::int32_t, kNumJoints> status{};       // per joint: 0 ok .. 3 critical (heat)
  std::array<double, kNumTouch> touch{};               // 0..1, kTouchNames order
  std::array<std::string, 4> robot_config;             // body id, body version, head id, version
};

}  // namespace stride::hal
