#include "simulator/world/robot_body.hpp"

namespace stride::sim {

Eigen::Vector3d RobotBody::centre_of_mass() const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double m = 0;
  for (int i = 0; i < link_count(); ++i) {
    const double mi = model_.links[i].inertial.mass;
    sum += mi * link_com(i);
    m += mi;
  }
  return m > 0 ? Eigen::Vector3d(sum / m) : sum;
}

Eigen::Vector3d RobotBody::centre_of_mass_velocity() const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double m = 0;
  for (int i = 0; i < link_count(); ++i) {
    const double mi = model_.links[i].inertial.mass;
    sum += mi * link_com_velocity(i);
    m += mi;
  }
  return m > 0 ? Eigen::Vector3d(sum / m) : sum;
}

}  // namespace stride::sim
