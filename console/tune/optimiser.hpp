#pragma once
// The search itself, from pagmo (Debian libpagmo-dev): generational particle swarm (pso_gen)
// whose every generation goes to one batch evaluation, which the tuner runs as one sweep. pagmo's
// headers stay in optimiser.cpp. Deterministic: the same bounds, sizes, seed and objectives give
// the same candidates, so a search is replayed (resumed) by feeding it the recorded objectives.
#include <cstdint>
#include <functional>
#include <vector>

namespace stride::tune {

struct SearchSettings {
  std::vector<double> lower, upper;  // per parameter
  int population = 8;                // candidates per generation
  int generations = 4;               // after the first (random) generation
  std::uint64_t seed = 1;            // below 2^32
};

// One generation's candidates (a value per parameter each) -> their objectives, larger better.
using BatchObjective =
    std::function<std::vector<double>(const std::vector<std::vector<double>>& candidates)>;

// Calls `evaluate` generations + 1 times, in order (the first: the initial population); an
// exception it throws ends the search and propagates.
void run_search(const SearchSettings& settings, const BatchObjective& evaluate);

}  // namespace stride::tune
