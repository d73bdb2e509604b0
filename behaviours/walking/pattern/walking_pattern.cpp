#include "behaviours/walking/pattern/walking_pattern.hpp"

#include "behaviours/walking/pattern/point_mass_zmp.hpp"
#include "behaviours/walking/pattern/vertical_motion.hpp"

namespace stride::walking {

namespace {
const PatternParameters& validated(const PatternParameters& p) {
  validate(p);
  return p;
}
}  // namespace

HorizontalPattern::HorizontalPattern(const PatternParameters& p)
    : p_(validated(p)), forward_(p_), lateral_(p_), feet_(p_, forward_) {}

PatternSample HorizontalPattern::sample_with_height(double t, const Motion1d& z) const {
  const Motion1d x = forward_.at(t), y = lateral_.at(t);
  PatternSample s;
  s.t = t;
  s.waist = {x.p, y.p, z.p};
  s.waist_velocity = {x.v, y.v, z.v};
  s.waist_acceleration = {x.a, y.a, z.a};
  s.left_foot = feet_.foot(Foot::kLeft, t);
  s.right_foot = feet_.foot(Foot::kRight, t);
  s.support = feet_.support(t);
  s.zmp = point_mass_zmp(s.waist, s.waist_acceleration, p_.gravity);
  return s;
}

PatternSample StretchedKneePattern::sample(double t) const {
  return sample_with_height(t, waist_height(p_, t));
}

PatternSample ConventionalPattern::sample(double t) const {
  return sample_with_height(t, {p_.z_conventional, 0.0, 0.0});
}

}  // namespace stride::walking
