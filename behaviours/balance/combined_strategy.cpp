#include "behaviours/balance/combined_strategy.hpp"

#include <algorithm>

namespace stride::balance {

CombinedBoundaries combined_boundaries(const BalanceParams& p) {
  const HipBoundaries h = hip_boundaries(p);
  return {p.zmp_min + h.backward, p.zmp_max + h.forward};  // Eq. 7.37
}

BangBangPlan plan_combined(const BalanceParams& p, const ComState& s0) {
  BangBangPlan plan;
  plan.capture_point = capture_point(s0, p.omega());
  const double xi = plan.capture_point;
  plan.zmp = std::clamp(xi, p.zmp_min, p.zmp_max);
  const double shift = xi - plan.zmp;  // Eq. 7.36: what the hip has to add
  const HipBoundaries h = hip_boundaries(p);
  plan.recoverable = shift >= h.backward && shift <= h.forward;
  if (shift == 0.0) {
    plan.profile = BangBang{};
  } else if (plan.recoverable) {
    const double tau = shift > 0 ? p.tau_forward : p.tau_backward;
    const auto profile = bang_bang_for_shift(p, tau, shift);
    plan.recoverable = profile.has_value();
    if (profile) plan.profile = *profile;
  } else {
    plan.profile = shift > 0 ? h.forward_profile : h.backward_profile;
  }
  plan.theta_peak = bang_bang_state(p, s0, plan, plan.profile.t2).theta;
  return plan;
}

}  // namespace stride::balance
