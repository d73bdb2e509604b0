#pragma once
// Which solver settings a scene's walk outcome has converged at: each setting's ensemble is
// compared with a reference setting's, and the cheapest setting that agrees is the study setting.
#include <string>
#include <vector>

#include "console/ensemble/ensemble_summary.hpp"

namespace stride::ensemble {

struct Tolerance {
  double distance = 0.05;  // relative: kept walks' mean true distance and mean step count
  int lost = 2;            // walks lost (fell or tipped), out of the ensemble
};

// Whether `s` agrees with `reference` within `tol`; if not, `why` says which figure differs.
bool agrees(const EnsembleSummary& s, const EnsembleSummary& reference, const Tolerance& tol,
            std::string& why);

// The index of the agreeing summary with the least wall time per member, -1 if none agrees.
// The reference agrees with itself, so with a reference in the list there always is one.
int cheapest_agreeing(const std::vector<EnsembleSummary>& summaries, int reference,
                      const Tolerance& tol);

}  // namespace stride::ensemble
