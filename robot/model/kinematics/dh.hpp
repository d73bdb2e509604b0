#pragma once
// Elementary homogeneous transforms and the modified Denavit-Hartenberg link transform (App. B).
#include <Eigen/Geometry>

namespace stride::model {

inline Eigen::Isometry3d trans(double x, double y, double z) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  return t;
}

inline Eigen::Isometry3d rot(const Eigen::Vector3d& axis, double angle) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
  return t;
}
inline Eigen::Isometry3d rot_x(double a) {
  return rot(Eigen::Vector3d::UnitX(), a);
}
inline Eigen::Isometry3d rot_y(double a) {
  return rot(Eigen::Vector3d::UnitY(), a);
}
inline Eigen::Isometry3d rot_z(double a) {
  return rot(Eigen::Vector3d::UnitZ(), a);
}

// One row of a D-H table: alpha_{i-1}, a_{i-1}, d_i and the offset added to the joint angle.
struct DhRow {
  double alpha_prev = 0;
  double a_prev = 0;
  double d = 0;
  double theta_offset = 0;
};

// Rot(x, alpha_{i-1}) Trans(a_{i-1}, 0, 0) Rot(z, theta_i) Trans(0, 0, d_i) in closed form
// (Eq. B.1).
inline Eigen::Isometry3d dh_transform(const DhRow& row, double theta) {
  const double ct = std::cos(theta + row.theta_offset), st = std::sin(theta + row.theta_offset);
  const double ca = std::cos(row.alpha_prev), sa = std::sin(row.alpha_prev);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() << ct, -st, 0, st * ca, ct * ca, -sa, st * sa, ct * sa, ca;  // Eq. B.1
  t.translation() << row.a_prev, -row.d * sa, row.d * ca;
  return t;
}

}  // namespace stride::model
