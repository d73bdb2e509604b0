#pragma once
// ZMP of a point mass at the waist on level ground (Eq. 2.5 with zero angular momentum change,
// i.e. Eq. 3.16 with z_zmp = 0).
#include <Eigen/Core>

namespace stride::walking {

inline Eigen::Vector2d point_mass_zmp(const Eigen::Vector3d& position,
                                      const Eigen::Vector3d& acceleration, double gravity) {
  const double lever = position.z() / (acceleration.z() + gravity);  // Eq. 3.16
  return {position.x() - lever * acceleration.x(), position.y() - lever * acceleration.y()};
}

}  // namespace stride::walking
