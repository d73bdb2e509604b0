#include "simulator/render/camera.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace stride::render {

Eigen::Matrix4d view_matrix(const CameraView& c) {
  const Eigen::Vector3d f = (c.target - c.eye).normalized();
  Eigen::Vector3d up = c.up;
  if (std::abs(f.dot(up.normalized())) > 0.999) up = Eigen::Vector3d::UnitX();  // looking along up
  const Eigen::Vector3d s = f.cross(up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m.block<3, 1>(0, 3) = -m.block<3, 3>(0, 0) * c.eye;
  return m;
}

Eigen::Matrix4d projection_matrix(const CameraView& c) {
  const double t = 1.0 / std::tan(c.fov / 2);
  const double aspect = static_cast<double>(c.width) / c.height;
  const double n = c.near_plane, f = c.far_plane;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = t / aspect;
  p(1, 1) = t;
  p(2, 2) = (f + n) / (n - f);
  p(2, 3) = 2 * f * n / (n - f);
  p(3, 2) = -1;
  return p;
}

std::optional<Eigen::Vector2d> project_to_pixel(const CameraView& c, const Eigen::Vector3d& p) {
  const Eigen::Vector4d clip = projection_matrix(c) * view_matrix(c) * p.homogeneous();
  if (clip.w() <= 0) return std::nullopt;
  const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
  return Eigen::Vector2d((ndc.x() + 1) / 2 * c.width, (1 - ndc.y()) / 2 * c.height);
}

}  // namespace stride::render
