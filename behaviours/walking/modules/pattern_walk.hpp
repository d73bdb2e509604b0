#pragma once
// Open-loop walking (thesis Ch. 3 pattern, Sec. 4.3.4.2 speeds) as modules providing the
// WalkingJointRequest:
//   PatternWalk       stretched-knee pattern (StretchedKneePattern)
//   ConventionalWalk  constant-height bent-knee pattern (ConventionalPattern)
// Both require FrameInfo and JointSensorData, take WalkParameters, and also provide the WalkPlan
// (walk_plan.hpp: ZMP reference and next footsteps) from the sample they play. From the first frame
// they blend the measured pose into the pattern's first pose (interpolation_time), stand until
// start_delay, play the pattern at FrameInfo time, then hold its last pose.
#include <array>

#include "behaviours/posture/walking_joint_request.hpp"
#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride::behaviours {

inline constexpr double kWalkLegStiffness = 1.0;

// The request for one pattern sample: the leg IK angles (stiffness 1), arms and head from the
// Stand posture at Stand's default stiffness.
WalkingJointRequest walking_request(const walking::LegJoints& legs);

// Pattern time at a frame: seconds since the walk started (negative while standing).
double pattern_time(double frame_time, double first_frame_time, double start_delay);

// Standing up: `request` blended from the measured `start_pose` by a cosine (zero velocity at
// both ends) `elapsed` seconds into an `interpolation_time` long blend.
void blend_from_pose(std::array<double, hal::kNumJoints>& request,
                     const std::array<double, hal::kNumJoints>& start_pose, double elapsed,
                     double interpolation_time);

void register_walking_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
