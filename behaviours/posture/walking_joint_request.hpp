#pragma once
// The walking pattern generator's joint targets (thesis Ch. 3: leg IK of the planned waist and
// feet), before posture control and arm swing; LoLA order, like JointRequest.
#include <array>

#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {

struct WalkingJointRequest {
  std::array<double, hal::kNumJoints> position{};
  std::array<double, hal::kNumJoints> stiffness{};

  static constexpr std::string_view kTypeName = "WalkingJointRequest";
  static constexpr auto fields() {
    using W = WalkingJointRequest;
    return std::make_tuple(field("position", &W::position, "rad"),
                           field("stiffness", &W::stiffness, "", Range{0, 1}));
  }
};

}  // namespace stride
