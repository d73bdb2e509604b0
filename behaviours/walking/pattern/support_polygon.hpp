#pragma once
// The support polygon of a pattern sample: the support sole in single support, the hull of both
// soles in double support (robot/model/kinematics/support_polygon.hpp does the geometry).
#include <Eigen/Core>

#include "robot/model/kinematics/support_polygon.hpp"

namespace stride::walking {

struct PatternSample;

model::ConvexPolygon support_polygon(const PatternSample& s);
model::ConvexPolygon both_soles_polygon(const PatternSample& s);

// Signed distance of the sample's ZMP to its support polygon: >= 0 inside.
double zmp_margin(const PatternSample& s);

}  // namespace stride::walking
