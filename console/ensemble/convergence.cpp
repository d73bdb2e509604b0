#include "console/ensemble/convergence.hpp"

#include <cmath>
#include <cstdlib>

#include "console/experiments/experiment_options.hpp"

namespace stride::ensemble {
namespace {

// |a - b| within tol of |b|; an empty side agrees only with an empty side.
bool close(const Spread& a, const Spread& b, double tol) {
  if (a.n == 0 || b.n == 0) return a.n == b.n;
  return std::abs(a.mean - b.mean) <= tol * std::abs(b.mean);
}

}  // namespace

bool agrees(const EnsembleSummary& s, const EnsembleSummary& reference, const Tolerance& tol,
            std::string& why) {
  using experiments::fixed;
  why.clear();
  if (std::abs(s.lost - reference.lost) > tol.lost)
    why = "lost " + std::to_string(s.lost) + " vs " + std::to_string(reference.lost);
  else if (!close(s.true_distance, reference.true_distance, tol.distance))
    why = "distance " + fixed(s.true_distance.mean, 3) + " vs " +
          fixed(reference.true_distance.mean, 3) + " m";
  else if (!close(s.steps, reference.steps, tol.distance))
    why = "steps " + fixed(s.steps.mean, 1) + " vs " + fixed(reference.steps.mean, 1);
  return why.empty();
}

int cheapest_agreeing(const std::vector<EnsembleSummary>& summaries, int reference,
                      const Tolerance& tol) {
  int best = -1;
  std::string why;
  for (int i = 0; i < static_cast<int>(summaries.size()); ++i) {
    if (!agrees(summaries[i], summaries[reference], tol, why)) continue;
    if (best < 0 || summaries[i].wall_per_member < summaries[best].wall_per_member) best = i;
  }
  return best;
}

}  // namespace stride::ensemble
