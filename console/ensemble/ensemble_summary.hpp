#pragma once
// An ensemble's outcome as figures with their spread: how many walks fell or tipped past
// sim::kTipAngle, and mean, standard deviation and range of the kept walks' figures.
#include <string>
#include <vector>

#include "console/ensemble/ensemble_run.hpp"

namespace stride::ensemble {

struct Spread {
  int n = 0;
  double mean = 0, sd = 0, min = 0, max = 0;  // sd: sample standard deviation (0 for one value)
};
Spread spread_of(const std::vector<double>& values);

struct EnsembleSummary {
  int members = 0;
  int fell = 0;
  int lost = 0;  // fell or tipped
  // Over the kept walks (neither fell nor tipped).
  Spread true_distance, fk_distance, steps, foot_slip_net_x, foot_tilted_time;
  double real_time_factor = 0;  // simulated over wall seconds, summed over the members
  double wall_per_member = 0;   // s
};
EnsembleSummary summarize_ensemble(const std::vector<MemberOutcome>& members);

// "2.012 ± 0.031 [1.950, 2.061]", "-" without values.
std::string spread_text(const Spread& s, int decimals);

// Column titles and one row of cells for a summary, after a first column the caller names.
std::vector<std::string> summary_header();
std::vector<std::string> summary_cells(const EnsembleSummary& s);

}  // namespace stride::ensemble
