#include "behaviours/walking/steps/pose_target.hpp"

#include <cmath>

namespace stride::walking {

TargetVelocity velocity_toward(const Pose2& at, const Pose2& target, const StepLimits& limits) {
  const Eigen::Vector2d local = rotated(-at.yaw, target.x - at.x, target.y - at.y);
  const double yaw = wrap_angle(target.yaw - at.yaw);
  TargetVelocity out;
  out.arrived = local.norm() < kArrivedDistance && std::abs(yaw) < kArrivedYaw;
  if (out.arrived) return out;
  out.velocity = within_range(
      {local.x() / kApproachTime, local.y() / kApproachTime, yaw / kApproachTime}, limits);
  return out;
}

}  // namespace stride::walking
