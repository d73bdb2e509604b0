#pragma once
// Forward (x) waist motion: rhythmic steps by cosine speed profiles (Eq. 3.1, Eq. 3.2 and
// Eq. 3.4), development and decay steps by 4th-order velocity polynomials (Eq. 3.5, Eq. 3.6).
#include <array>
#include <vector>

#include "behaviours/walking/pattern/motion_sample.hpp"
#include "behaviours/walking/pattern/pattern_parameters.hpp"

namespace stride::walking {

// One rhythmic step (Eq. 3.1, Eq. 3.2, Eq. 3.4), u in [0, T_step] from the middle of a single
// support.
Motion1d rhythmic_step(const SpeedLevel& level, double T_s, double T_d, double u);

// Velocity polynomial V(u) = sum c[i] u^i of one development or decay step (Eq. 3.5).
struct VelocityQuartic {
  std::array<double, 5> c{};
  Motion1d at(double u) const;  // p is the distance covered since u = 0
  double jerk(double u) const;  // second derivative of the velocity
};

// The quartic of Eq. 3.6: from v_start to v_end over T_step with zero acceleration at both ends and
// the second velocity derivative at the end equal to that of the next rhythmic-shaped step.
VelocityQuartic development_quartic(double v_start, double v_end, double jerk_end, double T_step);
// The quartic of Eq. 3.6 mirrored in time for the decay phase: the jerk is prescribed at the start.
VelocityQuartic decay_quartic(double v_start, double v_end, double jerk_start, double T_step);

// Second derivative of the speed where a rhythmic step at `level` starts or ends (Eq. 3.6
// footnote 3): A_m * pi / T_s with A_m = pi (V_max - V_min) / (2 T_s).
double rhythmic_jerk(const SpeedLevel& level, double T_s);

// The whole walk's forward motion: development, rhythmic and decay steps joined at t = j T_step.
class ForwardMotion {
 public:
  explicit ForwardMotion(const PatternParameters& p);
  Motion1d at(double t) const;                          // rest before 0 and after duration()
  double step_start(int j) const { return start_[j]; }  // X_j = x(j T_step), j in [0, steps]
  int steps() const { return static_cast<int>(segments_.size()); }
  double duration() const { return T_step_ * steps(); }

 private:
  struct Segment {
    bool polynomial = false;
    VelocityQuartic quartic;  // when polynomial
    SpeedLevel level;         // when rhythmic
  };
  Motion1d segment_at(const Segment& s, double u) const;

  double T_step_, T_s_, T_d_;
  std::vector<Segment> segments_;
  std::vector<double> start_;
};

}  // namespace stride::walking
