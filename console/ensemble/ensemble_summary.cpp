#include "console/ensemble/ensemble_summary.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "console/experiments/experiment_options.hpp"

namespace stride::ensemble {

using experiments::fixed;

Spread spread_of(const std::vector<double>& values) {
  Spread s;
  s.n = static_cast<int>(values.size());
  if (values.empty()) return s;
  s.mean = std::accumulate(values.begin(), values.end(), 0.0) / s.n;
  double squares = 0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.sd = s.n > 1 ? std::sqrt(squares / (s.n - 1)) : 0.0;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  s.min = *lo;
  s.max = *hi;
  return s;
}

EnsembleSummary summarize_ensemble(const std::vector<MemberOutcome>& members) {
  EnsembleSummary s;
  s.members = static_cast<int>(members.size());
  std::vector<double> distance, fk, steps, slip, tilted;
  double simulated = 0, wall = 0;
  for (const MemberOutcome& m : members) {
    simulated += m.sim_seconds;
    wall += m.wall_seconds;
    const bool lost = m.walk.fell || m.walk.tipped != sim::Tip::None;
    s.fell += m.walk.fell ? 1 : 0;
    s.lost += lost ? 1 : 0;
    if (lost) continue;
    distance.push_back(m.walk.true_distance);
    fk.push_back(m.walk.fk_distance);
    steps.push_back(m.walk.steps);
    slip.push_back(m.walk.foot_slip_net_x);
    tilted.push_back(m.walk.foot_tilted_time);
  }
  s.true_distance = spread_of(distance);
  s.fk_distance = spread_of(fk);
  s.steps = spread_of(steps);
  s.foot_slip_net_x = spread_of(slip);
  s.foot_tilted_time = spread_of(tilted);
  s.real_time_factor = wall > 0 ? simulated / wall : 0;
  s.wall_per_member = members.empty() ? 0 : wall / s.members;
  return s;
}

std::string spread_text(const Spread& s, int decimals) {
  if (s.n == 0) return "-";
  return fixed(s.mean, decimals) + " ± " + fixed(s.sd, decimals) + " [" + fixed(s.min, decimals) +
         ", " + fixed(s.max, decimals) + "]";
}

std::vector<std::string> summary_header() {
  return {"fell",
          "lost",
          "true distance [m] (kept)",
          "fk distance [m]",
          "steps",
          "slip net x [m]",
          "edge time [s]",
          "x real time"};
}

std::vector<std::string> summary_cells(const EnsembleSummary& s) {
  return {std::to_string(s.fell) + "/" + std::to_string(s.members),
          std::to_string(s.lost) + "/" + std::to_string(s.members),
          spread_text(s.true_distance, 3),
          spread_text(s.fk_distance, 3),
          spread_text(s.steps, 1),
          spread_text(s.foot_slip_net_x, 3),
          spread_text(s.foot_tilted_time, 2),
          fixed(s.real_time_factor, 2)};
}

}  // namespace stride::ensemble
