#include "behaviours/balance/ankle_strategy.hpp"

#include <algorithm>
#include <cmath>

#include "behaviours/balance/lipm_solution.hpp"
#include "robot/core/error.hpp"

namespace stride::balance {

AnkleOpenLoopResult ankle_open_loop(const BalanceParams& p, const ComState& s0) {
  const double w = p.omega();
  AnkleOpenLoopResult r;
  r.capture_point = capture_point(s0, w);
  // Algorithm 1: f = -omega xdot0 - omega^2 x0, saturated at f_max / f_min.
  r.zmp = std::clamp(r.capture_point, p.zmp_min, p.zmp_max);
  r.recoverable = r.capture_point >= p.zmp_min && r.capture_point <= p.zmp_max;  // Eq. 7.13
  r.forcing = ankle_forcing(r.zmp, w);
  r.final_x =  // Eq. 7.14 as t grows
      r.recoverable ? -r.forcing / (w * w) : std::copysign(INFINITY, r.capture_point);
  return r;
}

PhaseLine ankle_front_boundary(const BalanceParams& p) {
  return {-p.omega(), p.omega() * p.zmp_max};
}

PhaseLine ankle_back_boundary(const BalanceParams& p) {
  return {-p.omega(), p.omega() * p.zmp_min};
}

double pd_demanded_zmp(const BalanceParams& p, const PdGains& k, const ComState& s, double x_set) {
  const double r = p.z_cm / p.g;
  return (1 + k.kp * r) * s.x + k.kd * r * s.v - k.kp * r * x_set;  // Eq. 7.18
}

namespace {
std::optional<PhasePoint> intersect(const PhaseLine& m, const PhaseLine& n) {
  const double ds = m.slope - n.slope;
  if (std::abs(ds) < 1e-9 * (std::abs(m.slope) + std::abs(n.slope))) return std::nullopt;
  const double x = (n.intercept - m.intercept) / ds;
  return PhasePoint{x, m.velocity_at(x)};
}
}  // namespace

ClosedLoopBoundaries closed_loop_boundaries(const BalanceParams& p, const PdGains& k,
                                            double x_set) {
  if (!(k.kd > 0))
    throw Error("closed-loop boundaries: kd must be positive (lines a, b need k1 > 0)");
  ClosedLoopBoundaries c;
  c.k1 = k.kd * p.z_cm / p.g;      // Eq. 7.20's k1
  c.k2 = 1 + k.kp * p.z_cm / p.g;  // and k2
  c.l1 = ankle_front_boundary(p);
  c.l2 = ankle_back_boundary(p);
  // Eq. 7.20 solved for xdot at the two ZMP borders.
  c.a = {-c.k2 / c.k1, (p.zmp_max + (c.k2 - 1) * x_set) / c.k1};
  c.b = {-c.k2 / c.k1, (p.zmp_min + (c.k2 - 1) * x_set) / c.k1};
  c.A = intersect(c.l1, c.a);
  c.B = intersect(c.l1, c.b);
  c.C = intersect(c.l2, c.a);
  c.D = intersect(c.l2, c.b);
  return c;
}

ComState pd_state(const PdGains& k, const ComState& s0, double x_set, double t) {
  // Eq. 7.16 in closed form: e = x - x_set obeys e'' + kd e' + kp e = 0; the root pattern picks it.
  const double e0 = s0.x - x_set, de0 = s0.v;
  const double disc = k.kd * k.kd / 4 - k.kp;
  const double a = -k.kd / 2;
  double e = 0, de = 0;
  if (std::abs(disc) < 1e-12 * std::max(1.0, k.kp)) {  // critically damped
    const double c2 = de0 - a * e0;
    e = (e0 + c2 * t) * std::exp(a * t);
    de = (c2 + a * (e0 + c2 * t)) * std::exp(a * t);
  } else if (disc < 0) {  // under-damped: a +- i wd
    const double wd = std::sqrt(-disc);
    const double c2 = (de0 - a * e0) / wd;
    const double ex = std::exp(a * t), cs = std::cos(wd * t), sn = std::sin(wd * t);
    e = ex * (e0 * cs + c2 * sn);
    de = ex * (a * (e0 * cs + c2 * sn) + wd * (-e0 * sn + c2 * cs));
  } else {  // over-damped (or unstable): two real roots
    const double r1 = a + std::sqrt(disc), r2 = a - std::sqrt(disc);
    const double c1 = (de0 - r2 * e0) / (r1 - r2), c2 = e0 - c1;
    e = c1 * std::exp(r1 * t) + c2 * std::exp(r2 * t);
    de = c1 * r1 * std::exp(r1 * t) + c2 * r2 * std::exp(r2 * t);
  }
  return {x_set + e, de};
}

ClosedLoopRun simulate_closed_loop(const BalanceParams& p, const PdGains& k, const ComState& s0,
                                   double x_set, double duration, double dt) {
  if (!(dt > 0) || !(duration > 0))
    throw Error("closed-loop simulation: dt and duration must be > 0");
  const double w2 = p.omega() * p.omega();
  auto applied_zmp = [&](const OdeState<2>& y) {
    return std::clamp(pd_demanded_zmp(p, k, {y[0], y[1]}, x_set), p.zmp_min,
                      p.zmp_max);  // Eq. 7.19
  };
  const std::function<OdeState<2>(double, const OdeState<2>&)> rhs = [&](double,
                                                                         const OdeState<2>& y) {
    return OdeState<2>{y[1], w2 * (y[0] - applied_zmp(y))};  // Eq. 7.1, the ZMP of Eq. 7.19
  };
  ClosedLoopRun run;
  OdeState<2> y{s0.x, s0.v};
  const auto steps = static_cast<long>(std::ceil(duration / dt));
  for (long i = 0; i <= steps; ++i) {
    const double demanded = pd_demanded_zmp(p, k, {y[0], y[1]}, x_set);
    const double zmp = applied_zmp(y);
    run.saturated = run.saturated || zmp != demanded;
    run.samples.push_back({i * dt, y[0], y[1], zmp, demanded, p.mass * p.g * zmp});  // Eq. 7.10
    if (std::abs(y[0]) > 100.0) break;  // fallen: the LIPM has left any meaningful range
    if (i < steps) y = rk4_step<2>(rhs, i * dt, y, dt);
  }
  const auto& last = run.samples.back();
  run.converged = std::abs(last.x - x_set) < 1e-3 && std::abs(last.v) < 1e-2;
  return run;
}

}  // namespace stride::balance
