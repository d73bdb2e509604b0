#include "behaviours/walking/steps/waist_step.hpp"

#include <algorithm>
#include <cmath>

#include "behaviours/walking/pattern/vertical_motion.hpp"

namespace stride::walking {

namespace {

// Mean speed of a rhythmic step over its speed swing: V_min + (V_max - V_min) (1 + tau_dsp) / 2.
double swing_share(const PatternParameters& p) {
  return 0.5 * (1.0 + p.tau_dsp);
}

Motion1d scaled(const Motion1d& m, double side) {
  return {side * m.p, side * m.v, side * m.a};
}

}  // namespace

SpeedLevel level_for_mean_speed(const PatternParameters& p, double mean) {
  const double reference =
      p.rhythmic.V_min + (p.rhythmic.V_max - p.rhythmic.V_min) * swing_share(p);
  const double ratio = reference > 0.0 ? (p.rhythmic.V_max - p.rhythmic.V_min) / reference : 0.0;
  const double dv = ratio * mean;
  const double v_min = mean - dv * swing_share(p);
  return {v_min, v_min + dv};
}

WaistStep::WaistStep(const PatternParameters& p, int index, StepKind kind, const StepVelocity& from,
                     const StepVelocity& to, const Pose2& start)
    : T_(p.T_step()),
      T_s_(p.T_s()),
      T_d_(p.T_d()),
      A_l_(p.A_l),
      omega_(p.omega()),
      z_min_(p.z_min),
      z_max_(p.z_max),
      index_(index),
      kind_(kind),
      to_(kind == StepKind::kLast ? StepVelocity{} : to),
      first_(first_step_cubic(p.A_l, p.omega(), p.T_step())),
      start_(start) {
  const StepVelocity v0 = kind == StepKind::kFirst ? StepVelocity{} : from;
  const SpeedLevel a = level_for_mean_speed(p, v0.forward),
                   b = level_for_mean_speed(p, to_.forward);
  if (kind == StepKind::kMiddle && v0.forward == to_.forward) {
    rhythmic_ = true;  // the rhythmic step of Sec. 3.3.1
    level_ = a;
  } else if (std::abs(to_.forward) >= std::abs(v0.forward)) {
    // Eq. 3.6: ends with the speed's second derivative of the rhythmic step that follows.
    forward_quartic_ = development_quartic(a.V_min, b.V_min, rhythmic_jerk(b, T_s_), T_);
  } else {
    // Eq. 3.6 mirrored: starts with that of the rhythmic step before.
    forward_quartic_ = decay_quartic(a.V_min, b.V_min, rhythmic_jerk(a, T_s_), T_);
  }
  sideways_ = development_quartic(v0.sideways, to_.sideways, 0.0, T_);
  turn_ = development_quartic(v0.turn, to_.turn, 0.0, T_);
  end_ = frame_at(T_);
}

Motion1d WaistStep::forward(double u) const {
  return rhythmic_ ? rhythmic_step(level_, T_s_, T_d_, u) : forward_quartic_.at(u);
}

Motion1d WaistStep::sway(double u) const {
  if (kind_ == StepKind::kFirst) return first_.at(u);  // Eq. 3.7, the cubic solved from Eq. 3.8
  if (kind_ == StepKind::kLast) {
    // The first step played backwards, on the side where the sway arrives: the walk ends with
    // the waist back between the feet.
    const double side = (index_ + 1) % 2 == 0 ? 1.0 : -1.0;
    const Motion1d m = first_.at(T_ - u);
    return {side * m.p, -side * m.v, side * m.a};
  }
  const double w = omega_ * (index_ * T_ + u - T_);  // Eq. 3.9, t_0 = T_step
  return scaled({std::cos(w), -omega_ * std::sin(w), -omega_ * omega_ * std::cos(w)}, A_l_);
}

LocalMotion WaistStep::local(double u) const {
  return {forward(u), sideways_.at(u), turn_.at(u), sway(u),
          sagittal_step(z_min_, z_max_, T_s_, T_d_, u)};
}

Pose2 WaistStep::frame_at(double u) const {
  u = std::clamp(u, 0.0, T_);
  // Simpson's rule over panels of at most 5 ms: the integrand is smooth within each piece of
  // the position of Eq. 3.4, so the error stays below a micrometre over a step.
  const int n = 2 * std::max(1, static_cast<int>(std::ceil(u / 0.01)));
  const double h = u / n;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = 0; i <= n; ++i) {
    const double s = i * h;
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += weight * rotated(start_.yaw + turn_.at(s).p, forward(s).v, sideways_.at(s).v);
  }
  const Eigen::Vector2d d = sum * (h / 3.0);
  return {start_.x + d.x(), start_.y + d.y(), wrap_angle(start_.yaw + turn_.at(u).p)};
}

}  // namespace stride::walking
