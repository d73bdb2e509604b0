#pragma once
// A pose on the ground (x, y forward and left, yaw about z) and composing them.
#include <cmath>
#include <numbers>

#include <Eigen/Core>

namespace stride::walking {

struct Pose2 {
  double x = 0.0, y = 0.0, yaw = 0.0;
};

// Angle in (-pi, pi].
inline double wrap_angle(double a) {
  return std::remainder(a, 2.0 * std::numbers::pi);
}

// A vector in the frame of `yaw` turned into the world frame.
inline Eigen::Vector2d rotated(double yaw, double x, double y) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {c * x - s * y, s * x + c * y};
}

// The point (x, y) of `frame`'s own coordinates, in the world frame.
inline Eigen::Vector2d point_in(const Pose2& frame, double x, double y) {
  return Eigen::Vector2d(frame.x, frame.y) + rotated(frame.yaw, x, y);
}

}  // namespace stride::walking
