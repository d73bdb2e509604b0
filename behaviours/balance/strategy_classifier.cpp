#include "behaviours/balance/strategy_classifier.hpp"
#include "robot/framework/enum_names.hpp"

namespace stride::balance {

std::string_view to_string(Strategy s) {
  return enum_name(s);
}

Classification classify(const BalanceParams& p, const ComState& s0) {
  validate(p);
  Classification c;
  c.capture_point = capture_point(s0, p.omega());
  const HipBoundaries hb = hip_boundaries(p);
  const CombinedBoundaries cb = combined_boundaries(p);
  c.ankle = {p.zmp_min, p.zmp_max};
  c.hip = {hb.backward, hb.forward};
  c.combined = {cb.backward, cb.forward};
  c.ankle_result = ankle_open_loop(p, s0);
  c.hip_plan = plan_hip(p, s0);
  c.combined_plan = plan_combined(p, s0);
  c.ankle_recovers = c.ankle_result.recoverable;
  c.hip_recovers = c.hip_plan.recoverable;
  c.combined_recovers = c.combined_plan.recoverable;
  if (c.ankle_recovers)
    c.strategy = Strategy::ankle;
  else if (c.hip_recovers)
    c.strategy = Strategy::hip;
  else if (c.combined_recovers)
    c.strategy = Strategy::combined;
  return c;
}

}  // namespace stride::balance
