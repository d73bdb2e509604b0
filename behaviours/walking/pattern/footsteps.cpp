#include "behaviours/walking/pattern/footsteps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stride::walking {

Eigen::Vector2d cycloid(double distance, double H_foot, double progress) {
  const double psi = 2.0 * std::numbers::pi * std::clamp(progress, 0.0, 1.0);
  const double alpha = distance / (2.0 * std::numbers::pi);
  // delta * alpha = H_foot / 2, so the height needs no division by a possibly zero alpha.
  return {alpha * (psi - std::sin(psi)), 0.5 * H_foot * (1.0 - std::cos(psi))};  // Eq. 3.11
}

double cycloid_share(double progress) {
  const double psi = 2.0 * std::numbers::pi * std::clamp(progress, 0.0, 1.0);
  return (psi - std::sin(psi)) / (2.0 * std::numbers::pi);  // Eq. 3.11
}

double synchronisation_alpha(const SpeedLevel& level, double T_s, double T_d) {
  return (level.V_max * T_d + level.V_min * T_s) / std::numbers::pi;  // Eq. 3.15
}

Footsteps::Footsteps(const PatternParameters& p, const ForwardMotion& forward)
    : T_step_(p.T_step()),
      T_s_(p.T_s()),
      d_0_(p.d_0),
      H_foot_(p.H_foot),
      steps_(forward.steps()),
      footholds_(forward.steps() + 1) {
  for (int j = 0; j <= steps_; ++j) footholds_(j) = forward.step_start(j);
}

double Footsteps::foothold(int j) const {
  return footholds_(std::clamp(j, 0, steps_));
}

double Footsteps::swing_start(int j) const {
  return std::max(0.0, j * T_step_ - T_s_);
}
double Footsteps::swing_end(int j) const {
  return std::min(steps_ * T_step_, j * T_step_ + T_s_);
}

Eigen::Vector3d Footsteps::foot(Foot f, double t) const {
  const double y = f == Foot::kLeft ? d_0_ : -d_0_;
  if (!(t > 0.0)) return {0.0, y, 0.0};  // also NaN: before the walk
  if (t >= steps_ * T_step_) return {foothold(steps_), y, 0.0};
  // Latest swing of this foot that has started by t.
  int j = std::min(static_cast<int>(std::floor((t + T_s_) / T_step_)), steps_);
  if (j >= 0 && swing_foot(j) != f) --j;
  if (j < 0) return {0.0, y, 0.0};
  if (t >= swing_end(j)) return {foothold(j + 1), y, 0.0};
  const double from = foothold(j - 1), to = foothold(j + 1);
  const double progress = (t - swing_start(j)) / (swing_end(j) - swing_start(j));
  const Eigen::Vector2d c = cycloid(to - from, H_foot_, progress);  // the cycloid of Eq. 3.11
  return {from + c.x(), y, c.y()};
}

SupportPhase Footsteps::support(double t) const {
  if (!(t > 0.0 && t < steps_ * T_step_)) return SupportPhase::kDouble;
  const int k = static_cast<int>(std::floor(t / T_step_ + 0.5));  // nearest boundary
  if (t < swing_start(k) || t >= swing_end(k)) return SupportPhase::kDouble;
  return swing_foot(k) == Foot::kLeft ? SupportPhase::kRight : SupportPhase::kLeft;
}

}  // namespace stride::walking
