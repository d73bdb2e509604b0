#pragma once
// Support polygon of the NAO soles on level ground: one sole rectangle in single support, the
// convex hull of both in double support (sole placement from nao_dimensions.hpp).
#include <vector>

#include <Eigen/Core>

#include "behaviours/walking/pattern/footsteps.hpp"

namespace stride::walking {

struct PatternSample;

using Polygon = std::vector<Eigen::Vector2d>;  // counter-clockwise

// The four sole corners of a foot whose sole-frame origin is at `origin` (right foot mirrored).
Polygon sole_corners(Foot foot, const Eigen::Vector3d& origin);

// Andrew's monotone chain; counter-clockwise, no repeated point.
Polygon convex_hull(Polygon points);

// Polygon of the feet on the ground at the sample's support phase.
Polygon support_polygon(const PatternSample& s);

// Smallest signed distance of p to the polygon's edge lines: >= 0 inside, < 0 outside.
double inside_margin(const Polygon& ccw, const Eigen::Vector2d& p);

}  // namespace stride::walking
