#pragma once
// Measured joint state, LoLA joint order (robot/hal/joint_id.hpp).
#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {

struct JointSensorData {
  STRIDE_FIELDS(JointSensorData);
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), position, "rad", {}, hal::kJointNames){};
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), current, "A", {}, hal::kJointNames){};
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), temperature, "degC", {}, hal::kJointNames){};
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), stiffness, "", {}, hal::kJointNames){};

  static constexpr std::string_view kTypeName = "JointSensorData";
};

}  // namespace stride
