#pragma once
// What a controller sends each control frame: per joint a mode and its set point, LoLA order.
#include <array>

#include "robot/hal/joint_id.hpp"

namespace stride::hal {

enum class ServoMode : int { Position, Torque };

struct ActuatorFrame {
  std::array<ServoMode, kNumJoints> mode{};    // Position unless a controller commands torque
  std::array<double, kNumJoints> position{};   // rad, used in Position mode
  std::array<double, kNumJoints> stiffness{};  // 0..1, scales the available torque
  std::array<double, kNumJoints> torque{};     // N*m at the joint, used in Torque mode
};

}  // namespace stride::hal
