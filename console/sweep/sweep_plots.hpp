#pragma once
// Pictures of tallies (<plot tally x y series>): the y columns against x, one curve per value of
// the series column, as <out>/<tally>_<y...>.csv and .png.
#include <vector>

#include "console/sweep/sweep_output.hpp"
#include "console/sweep/tally.hpp"

namespace stride::sweep {

// Writes each plot's CSV, and its PNG when `png` (gnuplot renders it); throws stride::Error
// naming the plot's line when a column is unknown.
void write_sweep_plots(const SweepSpec& spec, const std::vector<TallyTable>& tallies,
                       const SweepOutput& output, bool png);

}  // namespace stride::sweep
