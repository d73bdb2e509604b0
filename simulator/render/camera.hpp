#pragma once
// A pinhole camera: where it is, what it looks at, and the matrices OpenGL needs (column-major,
// as Eigen stores them).
#include <optional>

#include <Eigen/Core>

namespace stride::render {

struct CameraView {
  Eigen::Vector3d eye{1.0, -0.8, 0.5};
  Eigen::Vector3d target{0, 0, 0.25};
  Eigen::Vector3d up{0, 0, 1};
  double fov = 0.8;  // vertical, rad
  int width = 640, height = 480;
  double near_plane = 0.02, far_plane = 50.0;
};

// World -> camera (camera looks along -z, y up).
Eigen::Matrix4d view_matrix(const CameraView& c);
// Camera -> clip coordinates for the vertical field of view and the image's aspect ratio.
Eigen::Matrix4d projection_matrix(const CameraView& c);
// Pixel (x right, y down, pixel centres at .5) where a world point appears; none behind the eye.
std::optional<Eigen::Vector2d> project_to_pixel(const CameraView& c, const Eigen::Vector3d& p);

}  // namespace stride::render
