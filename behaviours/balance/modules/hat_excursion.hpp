#pragma once
// One bang-bang excursion of the head-arms-trunk about the hips (thesis Eq. 7.24, Eq. 7.27) as a
// position trajectory: the HAT angle the hip pitch servos are sent to, then a hold at the peak
// and a smooth return to the posture.
#include <algorithm>
#include <cmath>
#include <optional>

#include "behaviours/balance/hip_strategy.hpp"
#include "behaviours/balance/modules/balance_actuation.hpp"
#include "behaviours/balance/modules/balance_representations.hpp"

namespace stride::behaviours {

struct HatExcursion {
  balance::BalanceParams params;
  balance::ComState s0;
  balance::BangBangPlan plan;
  double start = 0;

  // HAT angle at time `now`; empty once the excursion is over.
  std::optional<double> theta(double now, double hold_time, double return_time) const {
    const double t = now - start;
    const double t2 = plan.profile.t2;
    const double peak = balance::bang_bang_state(params, s0, plan, t2).theta;
    if (t < t2) return balance::bang_bang_state(params, s0, plan, t).theta;
    if (t < t2 + hold_time) return peak;
    const double s = (t - t2 - hold_time) / return_time;
    if (s >= 1) return std::nullopt;
    return peak * (1 - smooth_ramp(s));
  }
};

// The HAT angle within the hip pitch joints' range of motion from the standing posture.
inline double clamp_theta(const BalanceModel& m, double theta) {
  return std::clamp(theta, m.theta_max_backward, m.theta_max_forward);
}

// The flywheel of Sec. 7.4 has no weight: a real trunk bent by theta carries the CoM along by
// m_HAT d sin(theta) / m; tilting the whole body about the ankles by the returned angle (forward
// > 0) takes it back.
inline double com_keeping_tilt(const BalanceModel& m, double theta) {
  const double d = std::sqrt(m.hat_inertia / m.hat_mass);
  return -m.hat_mass * d * std::sin(theta) / m.mass / m.com_height;
}

}  // namespace stride::behaviours
