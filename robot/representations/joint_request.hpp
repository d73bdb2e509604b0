#pragma once
// What the controller wants from every joint this frame, LoLA order; becomes the ActuatorFrame.
#include "robot/representations/hal_reflection.hpp"

namespace stride {

struct JointRequest {
  std::array<hal::ServoMode, hal::kNumJoints> mode{};
  std::array<double, hal::kNumJoints> position{};
  std::array<double, hal::kNumJoints> stiffness{};
  std::array<double, hal::kNumJoints> torque{};

  static constexpr std::string_view kTypeName = "JointRequest";
  static constexpr auto fields() {
    using R = JointRequest;
    return std::make_tuple(
        field("mode", &R::mode).named(hal::kJointNames),
        field("position", &R::position, "rad").named(hal::kJointNames),
        field("stiffness", &R::stiffness, "", Range{0, 1}).named(hal::kJointNames),
        field("torque", &R::torque, "N*m").named(hal::kJointNames));
  }
};

}  // namespace stride
