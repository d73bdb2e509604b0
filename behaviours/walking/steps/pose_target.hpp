#pragma once
// Walking to a pose: the velocity request that brings the walk frame to a target pose, slowing as
// it comes near, and when it has arrived.
#include "behaviours/walking/steps/pose2.hpp"
#include "behaviours/walking/steps/step_velocity.hpp"

namespace stride::walking {

struct TargetVelocity {
  StepVelocity velocity;  // in the axes of the walk frame `at`, within the limits' range
  bool arrived = false;   // within kArrivedDistance and kArrivedYaw: stand
};

inline constexpr double kApproachTime = 1.5;      // s: each error component over this
inline constexpr double kArrivedDistance = 0.02;  // m
inline constexpr double kArrivedYaw = 0.05;       // rad

TargetVelocity velocity_toward(const Pose2& at, const Pose2& target, const StepLimits& limits);

}  // namespace stride::walking
