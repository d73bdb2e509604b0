#include "behaviours/walking/modules/walk_plan.hpp"

namespace stride::walking {

namespace {

// The plan at t from its sample; `landing(f, t_end)` is where foot f stands once a swing ending
// at t_end has landed.
template <class Landing>
WalkPlan plan_from(const PatternSample& sample, const Footsteps& feet, double t,
                   const Landing& landing) {
  WalkPlan p;
  p.t = t;
  p.zmp = {sample.zmp.x(), sample.zmp.y()};
  p.support = static_cast<std::int64_t>(sample.support);            // kDouble 0, kLeft 1, kRight 2
  p.left_foot = {sample.left_foot.x(), sample.left_foot.y(), 0.0};  // the pattern walks straight
  p.right_foot = {sample.right_foot.x(), sample.right_foot.y(), 0.0};
  for (int j = 0; j < feet.swings() && p.steps < kWalkPlanSteps; ++j) {
    if (feet.swing_end(j) <= t) continue;  // landed already
    const Foot f = Footsteps::swing_foot(j);
    const Eigen::Vector3d at = landing(f, feet.swing_end(j));
    p.step_x[p.steps] = at.x();
    p.step_y[p.steps] = at.y();
    p.step_yaw[p.steps] = 0.0;
    p.step_foot[p.steps] = f == Foot::kLeft ? 1 : 2;
    ++p.steps;
  }
  return p;
}

}  // namespace

WalkPlan walk_plan(const PatternSample& sample, const Footsteps& feet, double t) {
  return plan_from(sample, feet, t, [&](Foot f, double at) { return feet.foot(f, at); });
}

WalkPlan walk_plan(const PatternSample& sample, const AdjustedPattern& pattern, double t) {
  return plan_from(sample, pattern.base().footsteps(), t,
                   [&](Foot f, double at) { return pattern.foot(f, at); });
}

}  // namespace stride::walking
