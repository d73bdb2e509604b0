#pragma once
// Lateral (y) waist motion in the transverse plane: a cubic first step (Eq. 3.7, Eq. 3.8), the
// cosine sway (Eq. 3.9), and the first step mirrored in time as the last step, which ends with
// the waist back between both feet. y is positive to the left.
#include <array>

#include "behaviours/walking/pattern/motion_sample.hpp"
#include "behaviours/walking/pattern/pattern_parameters.hpp"

namespace stride::walking {

// y(t) = a1 t + a2 t^2 + a3 t^3 for the first step (a0 = 0), solved from Eq. 3.8.
struct FirstStepCubic {
  std::array<double, 4> a{};  // a0..a3
  Motion1d at(double t) const;
};
FirstStepCubic first_step_cubic(double A_l, double omega, double T_step);

class LateralMotion {
 public:
  explicit LateralMotion(const PatternParameters& p);
  Motion1d at(double t) const;  // 0 before the walk and after steps * T_step

 private:
  double A_l_, omega_, T_step_;
  int steps_;
  FirstStepCubic first_;
};

}  // namespace stride::walking
