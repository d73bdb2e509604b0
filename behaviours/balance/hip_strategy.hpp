#pragma once
// Hip strategy with the bang-bang hip torque profile (thesis Sec. 7.4, Alg. 2).
#include <optional>

#include "behaviours/balance/balance_params.hpp"

namespace stride::balance {

// The torque of Eq. 7.24: +tau on [0, t1), -tau on [t1, t2), 0 afterwards.
struct BangBang {
  double tau = 0.0;
  double t1 = 0.0;
  double t2 = 0.0;
};
double bang_bang_torque(const BangBang& b, double t);

// How far the profile (Eq. 7.25) moves the capture point, tau/(m g) (1 - 2e^{-w t1} + e^{-w t2}).
double hip_capture_shift(const BalanceParams& p, const BangBang& b);

// The profile of Eq. 7.28 and Eq. 7.29 solved for t1, t2: the profile that stops the HAT exactly at
// theta_max. Empty when the HAT cannot reach theta_max from (theta0, theta_dot0) with this torque
// sign.
std::optional<BangBang> limit_bang_bang(const BalanceParams& p, double tau, double theta_max);

// The t1 formula after Eq. 7.28: the profile whose capture shift equals `shift`.
// Empty when no t1 >= 0 exists (shift of the wrong sign or beyond what tau can ever give).
std::optional<BangBang> bang_bang_for_shift(const BalanceParams& p, double tau, double shift);

// Capture-point interval (Eq. 7.30) [backward, forward] recoverable by the hip alone.
struct HipBoundaries {
  double backward = 0.0;
  double forward = 0.0;
  BangBang backward_profile, forward_profile;  // the saturated profiles (ROM limit reached)
};
HipBoundaries hip_boundaries(const BalanceParams& p);

// What a bang-bang plan (hip or combined) does from one initial state.
struct BangBangPlan {
  bool recoverable = false;
  double capture_point = 0.0;  // x0 + xdot0 / omega
  double zmp = 0.0;            // ankle ZMP held during the plan (0 for the pure hip strategy)
  BangBang profile;            // switching times t1, t2 (saturated profile if not recoverable)
  double theta_peak = 0.0;     // HAT angle where it comes to rest, Eq. 7.27 at t2
};

// Algorithm 2: pure hip strategy (ankle unactuated, ZMP under the ankle).
BangBangPlan plan_hip(const BalanceParams& p, const ComState& s0);

// Full state of the CoM + HAT model at time t under a plan (closed form of Eq. 7.23,
// Eq. 7.26 and Eq. 7.27, and of the combined-strategy trajectory, Eq. 7.34 under Eq. 7.35).
struct HipModelState {
  double x = 0, v = 0;              // CoM
  double theta = 0, theta_dot = 0;  // HAT angle about the hip
  double tau = 0;                   // hip torque
};
HipModelState bang_bang_state(const BalanceParams& p, const ComState& s0, const BangBangPlan& plan,
                              double t);

}  // namespace stride::balance
