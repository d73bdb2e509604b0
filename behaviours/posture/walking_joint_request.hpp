#pragma once
// The walking pattern generator's joint targets (thesis Ch. 3: leg IK of the planned waist and
// feet), before posture control and arm swing; LoLA order, like JointRequest.
#include <array>
#include <cstdint>

#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {

struct WalkingJointRequest {
  STRIDE_FIELDS(WalkingJointRequest);
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), position, "rad", {}, hal::kJointNames){};
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), stiffness, "", Range{0, 1},
               hal::kJointNames){};
  // Leg IK solutions outside the joint limits (pattern_joints.hpp's LegJoints::beyond_limits bits
  // for this frame) and the frames since the walk started that had any.
  STRIDE_FIELD(std::uint32_t, ik_beyond_limits) = 0;
  STRIDE_FIELD(std::int64_t, ik_beyond_limit_frames) = 0;

  static constexpr std::string_view kTypeName = "WalkingJointRequest";
};

}  // namespace stride
