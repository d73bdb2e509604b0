#include "behaviours/walking/pattern/vertical_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stride::walking {

Motion1d sagittal_step(double z_min, double z_max, double T_s, double T_d, double u) {
  const double A_s = 0.5 * (z_max - z_min);  // sagittal oscillation amplitude
  const double k = std::numbers::pi / T_s;
  if (u >= T_s && u < T_d) return {z_min, 0.0, 0.0};
  const double w = k * (u < T_s ? u - T_s : u - T_d);
  return {A_s * (1.0 - std::cos(w)) + z_min, A_s * k * std::sin(w),
          A_s * k * k * std::cos(w)};  // Eq. 3.10
}

Motion1d waist_height(const PatternParameters& p, double t) {
  const double T = p.T_step();
  if (!(t > 0.0 && t < p.steps * T)) return {p.z_max, 0.0, 0.0};
  const int j = std::min(static_cast<int>(t / T), p.steps - 1);
  return sagittal_step(p.z_min, p.z_max, p.T_s(), p.T_d(), t - j * T);
}

}  // namespace stride::walking
