#pragma once
// Support polygon of one or two NAO soles (rectangles of nao_dimensions.hpp, right foot mirrored)
// projected on the ground plane, and the signed stability margin of a point against it.
#include <array>
#include <span>

#include <Eigen/Geometry>

#include "robot/model/kinematics/nao_chains.hpp"

namespace stride::model {

// Convex polygon, counter-clockwise, fixed capacity (two rectangles at most): no allocation.
struct ConvexPolygon {
  static constexpr int kCapacity = 8;
  std::array<Eigen::Vector2d, kCapacity> vertices;
  int size = 0;
  double area() const;
};

// The four sole corners in the sole frame (z = 0), counter-clockwise.
std::array<Eigen::Vector2d, 4> sole_corners(Side side);

struct FootContact {
  Side side = Side::Left;
  Eigen::Isometry3d sole = Eigen::Isometry3d::Identity();  // sole frame in the reference frame
};

// Convex hull of the soles' corners projected on the reference frame's xy plane.
ConvexPolygon support_polygon(std::span<const FootContact> feet);

// Convex hull of up to ConvexPolygon::kCapacity points (Andrew's monotone chain).
ConvexPolygon convex_hull(std::span<const Eigen::Vector2d> points);

// Signed distance of p to the polygon's boundary: positive inside, negative outside.
double stability_margin(const Eigen::Vector2d& p, const ConvexPolygon& polygon);

}  // namespace stride::model
