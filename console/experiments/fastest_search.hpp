#pragma once
// `stride experiment fastest`: the fastest stable walk, searched through the grid of
// scenes/experiments/fastest.sweep.xml in the thesis' order. Per floor the target speed rises
// level by level; at each target the settings are tried in turn (each a small sweep over the
// seeds, run by the engine) until one is stable; the search ends at the first target where none
// is. The fastest measured walk among the stable ones wins, not the highest target.
#include <iosfwd>

#include "console/sweep/sweep_request.hpp"

namespace stride::experiments {

// Runs the search for the request's sweep (its file must have the factors floor, target and
// setting and the record column stable); prints each step and the table to `out`. The exit
// code: 0, or 130 when interrupted.
int run_fastest_search(const sweep::SweepRequest& request, std::ostream& out);

}  // namespace stride::experiments
