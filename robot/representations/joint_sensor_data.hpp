#pragma once
// Measured joint state, LoLA joint order (robot/hal/joint_id.hpp).
#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {

struct JointSensorData {
  std::array<double, hal::kNumJoints> position{};
  std::array<double, hal::kNumJoints> current{};
  std::array<double, hal::kNumJoints> temperature{};
  std::array<double, hal::kNumJoints> stiffness{};

  static constexpr std::string_view kTypeName = "JointSensorData";
  static constexpr auto fields() {
    using J = JointSensorData;
    return std::make_tuple(field("position", &J::position, "rad").named(hal::kJointNames),
                           field("current", &J::current, "A").named(hal::kJointNames),
                           field("temperature", &J::temperature, "degC").named(hal::kJointNames),
                           field("stiffness", &J::stiffness).named(hal::kJointNames));
  }
};

}  // namespace stride
