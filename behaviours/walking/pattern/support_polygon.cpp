#include "behaviours/walking/pattern/support_polygon.hpp"

#include <Eigen/Geometry>

#include "behaviours/walking/pattern/walking_pattern.hpp"

namespace stride::walking {

namespace {
model::FootContact contact(model::Side side, const Eigen::Vector3d& sole) {
  model::FootContact c;
  c.side = side;
  c.sole.translation() = sole;  // soles flat, parallel to the world axes
  return c;
}
}  // namespace

model::ConvexPolygon both_soles_polygon(const PatternSample& s) {
  const model::FootContact feet[] = {contact(model::Side::Left, s.left_foot),
                                     contact(model::Side::Right, s.right_foot)};
  return model::support_polygon(feet);
}

model::ConvexPolygon support_polygon(const PatternSample& s) {
  if (s.support == SupportPhase::kDouble) return both_soles_polygon(s);
  const model::FootContact foot[] = {s.support == SupportPhase::kLeft
                                         ? contact(model::Side::Left, s.left_foot)
                                         : contact(model::Side::Right, s.right_foot)};
  return model::support_polygon(foot);
}

double zmp_margin(const PatternSample& s) {
  return model::stability_margin(s.zmp, support_polygon(s));
}

}  // namespace stride::walking
