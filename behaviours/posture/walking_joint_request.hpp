#pragma once
// The walking pattern generator's joint targets (thesis Ch. 3: leg IK of the planned waist and
// feet), before posture control and arm swing; LoLA order, like JointRequest.
#include <array>
#include <cstdint>

#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {

struct WalkingJointRequest {
  std::array<double, hal::kNumJoints> position{};
  std::array<double, hal::kNumJoints> stiffness{};
  // Leg IK solutions outside the joint limits (pattern_joints.hpp's LegJoints::beyond_limits bits
  // for this frame) and the frames since the walk started that had any.
  std::uint32_t ik_beyond_limits = 0;
  std::int64_t ik_beyond_limit_frames = 0;

  static constexpr std::string_view kTypeName = "WalkingJointRequest";
  static constexpr auto fields() {
    using W = WalkingJointRequest;
    return std::make_tuple(
        field("position", &W::position, "rad").named(hal::kJointNames),
        field("stiffness", &W::stiffness, "", Range{0, 1}).named(hal::kJointNames),
        field("ik_beyond_limits", &W::ik_beyond_limits),
        field("ik_beyond_limit_frames", &W::ik_beyond_limit_frames));
  }
};

}  // namespace stride
