#include "behaviours/walking/pattern/lateral_motion.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace stride::walking {

Motion1d FirstStepCubic::at(double t) const {
  return {((a[3] * t + a[2]) * t + a[1]) * t + a[0], (3 * a[3] * t + 2 * a[2]) * t + a[1],
          6 * a[3] * t + 2 * a[2]};
}

FirstStepCubic first_step_cubic(double A_l, double omega, double T_step) {
  const double T = T_step;
  Eigen::Matrix3d A;         // Eq. 3.8 as A x = b with x = (a3, a2, a1)
  A << T * T * T, T * T, T,  //
      3 * T * T, 2 * T, 1,   //
      6 * T, 2, 0;
  const Eigen::Vector3d x = A.partialPivLu().solve(Eigen::Vector3d(A_l, 0, -omega * omega * A_l));
  return {{0.0, x(2), x(1), x(0)}};
}

LateralMotion::LateralMotion(const PatternParameters& p)
    : A_l_(p.A_l),
      omega_(p.omega()),
      T_step_(p.T_step()),
      steps_(p.steps),
      first_(first_step_cubic(p.A_l, p.omega(), p.T_step())) {}

Motion1d LateralMotion::at(double t) const {
  const double end = steps_ * T_step_;
  if (!(t > 0.0 && t < end)) return {};
  if (t < T_step_) return first_.at(t);  // Eq. 3.7
  if (t > end - T_step_) {
    // Last step: the first step played backwards, on the side where the cosine arrives.
    const double side = (steps_ % 2 == 0) ? 1.0 : -1.0;  // cos((steps - 2) pi)
    const Motion1d m = first_.at(end - t);
    return {side * m.p, -side * m.v, side * m.a};
  }
  const double w = omega_ * (t - T_step_);  // Eq. 3.9, t_0 = T_step
  return {A_l_ * std::cos(w), -A_l_ * omega_ * std::sin(w), -A_l_ * omega_ * omega_ * std::cos(w)};
}

}  // namespace stride::walking
