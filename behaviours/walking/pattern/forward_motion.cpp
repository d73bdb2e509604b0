#include "behaviours/walking/pattern/forward_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

namespace stride::walking {

namespace {
constexpr double kPi = std::numbers::pi;
}

Motion1d rhythmic_step(const SpeedLevel& level, double T_s, double T_d, double u) {
  const double dv = level.V_max - level.V_min, sv = level.V_min + level.V_max;
  const double A_m = kPi * dv / (2.0 * T_s);  // maximum acceleration (Eq. 3.2)
  if (u < T_s) {                              // speed-up, the first lines of:
    const double w = kPi * u / T_s;
    // Eq. 3.4 (position)
    // Eq. 3.1 (speed)
    // Eq. 3.2 (acceleration)
    return {0.5 * sv * u - dv * T_s / (2.0 * kPi) * std::sin(w),
            0.5 * dv * (1.0 - std::cos(w)) + level.V_min, A_m * std::sin(w)};
  }
  if (u < T_d) return {0.5 * sv * T_s + level.V_max * (u - T_s), level.V_max, 0.0};
  const double w = kPi * (u - T_d - T_s) / T_s;  // slow-down (third lines)
  return {0.5 * dv * (T_d - T_s) + 0.5 * sv * u - dv * T_s / (2.0 * kPi) * std::sin(w),
          0.5 * dv * (1.0 - std::cos(w)) + level.V_min, A_m * std::sin(w)};
}

Motion1d VelocityQuartic::at(double u) const {
  Motion1d m;
  double pw = 1.0;  // u^i
  for (int i = 0; i < 5; ++i) {
    m.p += c[i] * pw * u / (i + 1);  // V of Eq. 3.5, integrated
    m.v += c[i] * pw;                // Eq. 3.5
    if (i < 4) m.a += (i + 1) * c[i + 1] * pw;
    pw *= u;
  }
  return m;
}

double VelocityQuartic::jerk(double u) const {
  return 2.0 * c[2] + 6.0 * c[3] * u + 12.0 * c[4] * u * u;
}

VelocityQuartic development_quartic(double v_start, double v_end, double jerk_end, double T_step) {
  // V(0) = v_start and V'(0) = 0 fix c0, c1; the three conditions at T_step give c2..c4.
  const double T = T_step;
  Eigen::Matrix3d A;
  A << T * T, T * T * T, T * T * T * T,  //
      2 * T, 3 * T * T, 4 * T * T * T,   //
      2, 6 * T, 12 * T * T;
  // Eq. 3.6
  const Eigen::Vector3d x = A.partialPivLu().solve(Eigen::Vector3d(v_end - v_start, 0, jerk_end));
  return {{v_start, 0.0, x(0), x(1), x(2)}};
}

VelocityQuartic decay_quartic(double v_start, double v_end, double jerk_start, double T_step) {
  // V(0), V'(0) = 0 and V''(0) fix c0..c2; V(T) = v_end and V'(T) = 0 give c3, c4.
  const double T = T_step, c2 = 0.5 * jerk_start;
  Eigen::Matrix2d A;
  A << T * T * T, T * T * T * T,  //
      3 * T * T, 4 * T * T * T;
  const Eigen::Vector2d b(v_end - v_start - c2 * T * T, -2.0 * c2 * T);
  const Eigen::Vector2d x = A.partialPivLu().solve(b);
  return {{v_start, 0.0, c2, x(0), x(1)}};
}

double rhythmic_jerk(const SpeedLevel& level, double T_s) {
  const double A_m = kPi * (level.V_max - level.V_min) / (2.0 * T_s);
  return A_m * kPi / T_s;
}

ForwardMotion::ForwardMotion(const PatternParameters& p)
    : T_step_(p.T_step()), T_s_(p.T_s()), T_d_(p.T_d()) {
  // Development: rest -> development levels -> rhythmic, one polynomial step per arrow.
  std::vector<SpeedLevel> up = p.development;
  up.push_back(p.rhythmic);
  double v = 0.0;
  for (const SpeedLevel& level : up) {
    segments_.push_back(
        {true, development_quartic(v, level.V_min, rhythmic_jerk(level, T_s_), T_step_), {}});
    v = level.V_min;
  }
  for (int j = 0; j < p.rhythmic_steps(); ++j) segments_.push_back({false, {}, p.rhythmic});
  // Decay: rhythmic -> decay levels -> rest, the development phase mirrored in time.
  std::vector<SpeedLevel> down = p.decay;
  down.push_back({0.0, 0.0});
  SpeedLevel from = p.rhythmic;
  for (const SpeedLevel& level : down) {
    segments_.push_back(
        {true, decay_quartic(from.V_min, level.V_min, rhythmic_jerk(from, T_s_), T_step_), {}});
    from = level;
  }
  start_.push_back(0.0);
  for (const Segment& s : segments_) start_.push_back(start_.back() + segment_at(s, T_step_).p);
}

Motion1d ForwardMotion::segment_at(const Segment& s, double u) const {
  return s.polynomial ? s.quartic.at(u) : rhythmic_step(s.level, T_s_, T_d_, u);
}

Motion1d ForwardMotion::at(double t) const {
  if (!(t > 0.0)) return {0.0, 0.0, 0.0};  // also NaN
  if (t >= duration()) return {start_.back(), 0.0, 0.0};
  const int j = std::min(static_cast<int>(t / T_step_), steps() - 1);
  Motion1d m = segment_at(segments_[j], t - j * T_step_);
  m.p += start_[j];
  return m;
}

}  // namespace stride::walking
