#pragma once
// What the controller wants from every joint this frame, LoLA order; becomes the ActuatorFrame.
#include "robot/representations/hal_reflection.hpp"

namespace stride {

struct JointRequest {
  STRIDE_FIELDS(JointRequest);
  STRIDE_FIELD((std::array<hal::ServoMode, hal::kNumJoints>), mode, "", {}, hal::kJointNames){};
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), position, "rad", {}, hal::kJointNames){};
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), stiffness, "", Range{0, 1},
               hal::kJointNames){};
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), torque, "N*m", {}, hal::kJointNames){};

  static constexpr std::string_view kTypeName = "JointRequest";
};

}  // namespace stride
