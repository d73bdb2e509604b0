#pragma once
// Up-and-down waist motion in the sagittal plane (Eq. 3.10): highest at the middle of each
// single support, lowest through the double support; twice the lateral frequency.
#include "behaviours/walking/pattern/motion_sample.hpp"
#include "behaviours/walking/pattern/pattern_parameters.hpp"

namespace stride::walking {

// The height of Eq. 3.10 within one step, u in [0, T_step] from the middle of a single support.
Motion1d sagittal_step(double z_min, double z_max, double T_s, double T_d, double u);

// The walk's waist height: Eq. 3.10 every step, resting at z_max before and after.
Motion1d waist_height(const PatternParameters& p, double t);

}  // namespace stride::walking
