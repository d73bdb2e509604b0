#include "behaviours/walking/pattern/support_polygon.hpp"

#include <algorithm>
#include <limits>

#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::walking {

namespace {
double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}
}  // namespace

Polygon sole_corners(Foot foot, const Eigen::Vector3d& origin) {
  const double side = foot == Foot::kLeft ? 1.0 : -1.0;
  const Eigen::Vector2d c(origin.x() + nao::kSoleCentreX,
                          origin.y() + side * nao::kSoleCentreYLeft);
  const double hx = 0.5 * nao::kSoleLength, hy = 0.5 * nao::kSoleWidth;
  return {c + Eigen::Vector2d(-hx, -hy), c + Eigen::Vector2d(hx, -hy), c + Eigen::Vector2d(hx, hy),
          c + Eigen::Vector2d(-hx, hy)};
}

Polygon convex_hull(Polygon pts) {
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (pts.size() < 3) return pts;
  Polygon hull(2 * pts.size());
  std::size_t k = 0;
  for (const auto& p : pts) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

Polygon support_polygon(const PatternSample& s) {
  switch (s.support) {
    case SupportPhase::kLeft:
      return sole_corners(Foot::kLeft, s.left_foot);
    case SupportPhase::kRight:
      return sole_corners(Foot::kRight, s.right_foot);
    case SupportPhase::kDouble:
      break;
  }
  Polygon both = sole_corners(Foot::kLeft, s.left_foot);
  const Polygon right = sole_corners(Foot::kRight, s.right_foot);
  both.insert(both.end(), right.begin(), right.end());
  return convex_hull(both);
}

double inside_margin(const Polygon& ccw, const Eigen::Vector2d& p) {
  double margin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ccw.size(); ++i) {
    const Eigen::Vector2d& a = ccw[i];
    const Eigen::Vector2d& b = ccw[(i + 1) % ccw.size()];
    margin = std::min(margin, cross(a, b, p) / (b - a).norm());
  }
  return margin;
}

}  // namespace stride::walking
