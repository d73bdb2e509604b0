#include "behaviours/balance/hip_strategy.hpp"

#include <algorithm>
#include <cmath>

namespace stride::balance {

double bang_bang_torque(const BangBang& b, double t) {
  // Eq. 7.24 with u(t - T) = 1 for t >= T.
  return b.tau * ((t >= 0) - 2.0 * (t >= b.t1) + (t >= b.t2));
}

double hip_capture_shift(const BalanceParams& p, const BangBang& b) {
  const double w = p.omega();
  return b.tau / (p.mass * p.g) * (1 - 2 * std::exp(-w * b.t1) + std::exp(-w * b.t2));  // Eq. 7.25
}

std::optional<BangBang> limit_bang_bang(const BalanceParams& p, double tau, double theta_max) {
  const double alpha = tau / p.inertia;  // HAT angular acceleration
  const double dth = p.theta_dot0;
  // alpha t1^2 + 2 dth t1 + (dth^2 / (2 alpha) + theta0 - theta_max) = 0 (from Eq. 7.28, Eq. 7.29)
  const double radicand = dth * dth / 2 - alpha * (p.theta0 - theta_max);
  if (radicand < 0) return std::nullopt;
  const double root = std::copysign(std::sqrt(radicand), alpha);  // the root with t1 >= 0
  const double t1 = (-dth + root) / alpha;
  const double t2 = 2 * t1 + dth / alpha;  // Eq. 7.28
  if (t1 < 0 || t2 < t1) return std::nullopt;
  return BangBang{tau, t1, t2};
}

std::optional<BangBang> bang_bang_for_shift(const BalanceParams& p, double tau, double shift) {
  const double w = p.omega();
  const double c = p.inertia * p.theta_dot0 / tau;  // Eq. 7.28: t2 - 2 t1
  const double k = p.mass * p.g / tau * shift;
  const double radicand = std::exp(w * c) - 1 + k;
  if (radicand < 0) return std::nullopt;
  // The solution after Eq. 7.28 with the '-' sign so that t1 >= 0.
  const double u = std::exp(w * c) - std::exp(w * c / 2) * std::sqrt(radicand);
  if (!(u > 0) || u > 1 + 1e-15) return std::nullopt;
  const double t1 = std::max(0.0, -std::log(u) / w);
  const double t2 = 2 * t1 + c;
  if (t2 < t1) return std::nullopt;
  return BangBang{tau, t1, t2};
}

HipBoundaries hip_boundaries(const BalanceParams& p) {
  HipBoundaries h;
  if (auto f = limit_bang_bang(p, p.tau_forward, p.theta_max_forward)) {
    h.forward_profile = *f;
    h.forward = hip_capture_shift(p, *f);
  }
  if (auto b = limit_bang_bang(p, p.tau_backward, p.theta_max_backward)) {
    h.backward_profile = *b;
    h.backward = hip_capture_shift(p, *b);
  }
  return h;
}

namespace {
double hat_angle(const BalanceParams& p, const BangBang& b, double t) {
  auto sq = [&](double ts) { return t >= ts ? (t - ts) * (t - ts) : 0.0; };
  return p.theta0 + p.theta_dot0 * t +
         b.tau / p.inertia * (0.5 * sq(0) - sq(b.t1) + 0.5 * sq(b.t2));  // Eq. 7.27
}

double hat_rate(const BalanceParams& p, const BangBang& b, double t) {
  auto ramp = [&](double ts) { return t >= ts ? t - ts : 0.0; };
  return p.theta_dot0 + b.tau / p.inertia * (ramp(0) - 2 * ramp(b.t1) + ramp(b.t2));  // Eq. 7.26
}
}  // namespace

BangBangPlan plan_hip(const BalanceParams& p, const ComState& s0) {
  BangBangPlan plan;
  plan.capture_point = capture_point(s0, p.omega());
  const HipBoundaries h = hip_boundaries(p);
  const double xi = plan.capture_point;
  plan.recoverable = xi >= h.backward && xi <= h.forward;  // Eq. 7.30
  if (plan.recoverable) {
    auto f = bang_bang_for_shift(p, p.tau_forward, xi);
    auto b = bang_bang_for_shift(p, p.tau_backward, xi);
    plan.profile = f ? *f : (b ? *b : BangBang{});
    plan.recoverable = f.has_value() || b.has_value();
  } else {
    // Algorithm 2, lines 9-14: saturate at the boundary profile on the side of the push.
    plan.profile = xi > h.forward ? h.forward_profile : h.backward_profile;
  }
  plan.theta_peak = hat_angle(p, plan.profile, plan.profile.t2);
  return plan;
}

HipModelState bang_bang_state(const BalanceParams& p, const ComState& s0, const BangBangPlan& plan,
                              double t) {
  const double w = p.omega();
  const BangBang& b = plan.profile;
  const double gain = b.tau / (p.mass * p.g);
  auto ramp = [&](double ts) { return t >= ts ? std::cosh(w * (t - ts)) - 1 : 0.0; };
  auto dramp = [&](double ts) { return t >= ts ? w * std::sinh(w * (t - ts)) : 0.0; };
  const double e0 = s0.x - plan.zmp;
  HipModelState s;
  // Eq. 7.34 (Eq. 7.23 when the ZMP is 0) under the torque of Eq. 7.35
  s.x = e0 * std::cosh(w * t) + s0.v / w * std::sinh(w * t) + plan.zmp -
        gain * (ramp(0) - 2 * ramp(b.t1) + ramp(b.t2));
  s.v = e0 * w * std::sinh(w * t) + s0.v * std::cosh(w * t) -
        gain * (dramp(0) - 2 * dramp(b.t1) + dramp(b.t2));
  s.theta = hat_angle(p, b, t);
  s.theta_dot = hat_rate(p, b, t);
  s.tau = bang_bang_torque(b, t);
  return s;
}

}  // namespace stride::balance
