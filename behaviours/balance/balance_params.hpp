#pragma once
// Constant parameters of the sagittal balance models of thesis Ch. 7 (LIPM + hip flywheel).
#include <cmath>

namespace stride::balance {

// One set of numbers shared by the ankle, hip, combined and LQR analyses.
// Defaults: NAO H25 v4 (thesis Appendix A, 5.183 kg) and the values printed with Figs. 7.4, 7.9.
struct BalanceParams {
  double g = 9.81;                        // gravity, m/s^2
  double z_cm = 0.32;                     // constant CoM height, m
  double mass = 5.183;                    // total robot mass m, kg (Ch. 7 leaves it unprinted)
  double zmp_min = -0.056;                // back border of the support polygon, m
  double zmp_max = 0.103;                 // front border of the support polygon, m
  double inertia = 0.1;                   // HAT rotational inertia I about the hip, kg m^2
  double tau_forward = 16.0;              // hip torque for forward recovery tau_{n-f}, N m (> 0)
  double tau_backward = -16.0;            // hip torque for backward recovery tau_{n-b}, N m (< 0)
  double theta_max_forward = 1.772308;    // hip pitch ROM limit theta_{max-f}, rad
  double theta_max_backward = -0.485624;  // hip pitch ROM limit theta_{max-b}, rad
  double theta0 = 0.0;                    // initial HAT angle, rad
  double theta_dot0 = 0.0;                // initial HAT angular velocity, rad/s

  double omega() const { return std::sqrt(g / z_cm); }  // Eq. 7.1: omega^2 = g / z
};

// Horizontal CoM state (x, xdot) in one sagittal axis.
struct ComState {
  double x = 0.0;
  double v = 0.0;
};

// x + xdot / omega: the quantity every boundary of Ch. 7 is written in (Eq. 7.13,
// Eq. 7.30 and Eq. 7.37).
inline double capture_point(const ComState& s, double omega) {
  return s.x + s.v / omega;  // Eq. 7.13's left side
}

// Throws stride::Error naming the first field that makes the models meaningless.
void validate(const BalanceParams& p);

}  // namespace stride::balance
