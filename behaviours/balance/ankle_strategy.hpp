#pragma once
// Ankle strategy (thesis Sec. 7.3): open-loop capture region and PD-closed-loop boundaries.
#include <optional>
#include <vector>

#include "behaviours/balance/balance_params.hpp"

namespace stride::balance {

// A straight line xdot = slope * x + intercept in the (x, xdot) phase plane.
struct PhaseLine {
  double slope = 0.0;
  double intercept = 0.0;
  double velocity_at(double x) const { return slope * x + intercept; }
};

struct PhasePoint {
  double x = 0.0;
  double v = 0.0;
};

// --- Open loop (Sec. 7.3.1, Algorithm 1) ---

struct AnkleOpenLoopResult {
  bool recoverable = false;  // true when Eq. 7.13 holds with a ZMP inside the support polygon
  double capture_point = 0;  // x0 + xdot0 / omega
  double zmp = 0;            // ZMP applied: the capture point, or the saturated border (Alg. 1)
  double forcing = 0;        // f = -omega^2 zmp
  double final_x = 0;        // limit of x_cm(t) when recoverable (Eq. 7.14)
};

// Algorithm 1: which ZMP the ankle applies from s0 and whether x_cm(t) converges.
AnkleOpenLoopResult ankle_open_loop(const BalanceParams& p, const ComState& s0);

// Fig. 7.4 boundaries: l1 (ZMP at the front border) and l2 (ZMP at the back border).
PhaseLine ankle_front_boundary(const BalanceParams& p);  // l1: xdot = -omega x + omega zmp_max
PhaseLine ankle_back_boundary(const BalanceParams& p);   // l2: xdot = -omega x + omega zmp_min

// --- Closed loop with PD on the CoM (Sec. 7.3.2) ---

struct PdGains {
  double kp = 0.0;
  double kd = 0.0;
};

// ZMP (Eq. 7.18) demanded by the PD law (Eq. 7.16) at state s.
double pd_demanded_zmp(const BalanceParams& p, const PdGains& k, const ComState& s, double x_set);

// The four lines of Fig. 7.5 and their intersections; A = l1 x a, B = l1 x b, C = l2 x a,
// D = l2 x b. Points are empty when a, b run parallel to l1, l2 (kp = omega kd - omega^2).
struct ClosedLoopBoundaries {
  double k1 = 0, k2 = 0;  // k1 = kd z / g, k2 = 1 + kp z / g (Eq. 7.20)
  PhaseLine l1, l2, a, b;
  std::optional<PhasePoint> A, B, C, D;
};
ClosedLoopBoundaries closed_loop_boundaries(const BalanceParams& p, const PdGains& k,
                                            double x_set = 0.0);

// Analytic solution of xddot + kd xdot + kp x = kp x_set (Eq. 7.16, unsaturated ZMP).
ComState pd_state(const PdGains& k, const ComState& s0, double x_set, double t);

struct ClosedLoopSample {
  double t = 0, x = 0, v = 0;
  double zmp = 0;           // ZMP actually applied (saturated by Eq. 7.19)
  double demanded_zmp = 0;  // of Eq. 7.18, before saturation
  double ankle_torque = 0;  // tau_a = m g x_zmp (Eq. 7.10)
};

struct ClosedLoopRun {
  std::vector<ClosedLoopSample> samples;
  bool converged = false;  // |x - x_set| and |xdot| small at the end
  bool saturated = false;  // the demanded ZMP left the support polygon at some time
};

// RK4 of the PD-controlled LIPM whose ZMP is clipped to the support polygon (Eq. 7.17, Eq. 7.18,
// then Eq. 7.19): the ankle cannot push the ZMP beyond the sole, which is what makes a PD start
// diverge.
ClosedLoopRun simulate_closed_loop(const BalanceParams& p, const PdGains& k, const ComState& s0,
                                   double x_set, double duration, double dt);

}  // namespace stride::balance
