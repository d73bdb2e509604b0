#include "robot/model/kinematics/support_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "robot/core/error.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::model {
namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace

double ConvexPolygon::area() const {
  double a = 0;
  for (int i = 0; i < size; ++i) {
    const Eigen::Vector2d& p = vertices[i];
    const Eigen::Vector2d& q = vertices[(i + 1) % size];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return a / 2;
}

std::array<Eigen::Vector2d, 4> sole_corners(Side side) {
  const double cy = side == Side::Left ? nao::kSoleCentreYLeft : -nao::kSoleCentreYLeft;
  const double hx = nao::kSoleLength / 2, hy = nao::kSoleWidth / 2, cx = nao::kSoleCentreX;
  return {Eigen::Vector2d(cx - hx, cy - hy), Eigen::Vector2d(cx + hx, cy - hy),
          Eigen::Vector2d(cx + hx, cy + hy), Eigen::Vector2d(cx - hx, cy + hy)};
}

ConvexPolygon convex_hull(std::span<const Eigen::Vector2d> points) {
  constexpr int kCap = ConvexPolygon::kCapacity;
  if (points.size() > static_cast<size_t>(kCap))
    throw Error("convex_hull: at most " + std::to_string(kCap) + " points, got " +
                std::to_string(points.size()));
  std::array<Eigen::Vector2d, kCap> p;
  const int n = static_cast<int>(points.size());
  std::copy(points.begin(), points.end(), p.begin());
  // A span of the n points: GCC 12 cannot see n <= kCap through std::sort's unrolled insertion.
  const std::span<Eigen::Vector2d> filled(p.data(), std::min<size_t>(points.size(), kCap));
  std::sort(filled.begin(), filled.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::array<Eigen::Vector2d, 2 * kCap> h;
  int k = 0;
  for (int i = 0; i < n; ++i) {  // lower hull
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (int i = n - 2, lower = k + 1; i >= 0; --i) {  // upper hull
    while (k >= lower && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  ConvexPolygon out;
  out.size = n <= 1 ? n : k - 1;  // the last point repeats the first
  std::copy(h.begin(), h.begin() + out.size, out.vertices.begin());
  return out;
}

ConvexPolygon support_polygon(std::span<const FootContact> feet) {
  if (feet.size() > 2) throw Error("support_polygon: at most two feet");
  std::array<Eigen::Vector2d, 8> points;
  int n = 0;
  for (const FootContact& f : feet)
    for (const Eigen::Vector2d& c : sole_corners(f.side))
      points[n++] = (f.sole * Eigen::Vector3d(c.x(), c.y(), 0)).head<2>();
  return convex_hull(std::span<const Eigen::Vector2d>(points.data(), n));
}

double stability_margin(const Eigen::Vector2d& p, const ConvexPolygon& polygon) {
  const int n = polygon.size;
  if (n == 0) return -std::numeric_limits<double>::infinity();
  double nearest = std::numeric_limits<double>::infinity();
  bool inside = n >= 3;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = polygon.vertices[i];
    const Eigen::Vector2d& b = polygon.vertices[(i + 1) % n];
    nearest = std::min(nearest, segment_distance(p, a, b));
    if (cross(a, b, p) < 0) inside = false;  // right of a counter-clockwise edge
  }
  return inside ? nearest : -nearest;
}

}  // namespace stride::model
