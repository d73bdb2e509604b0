#pragma once
// What a finished search says: which parameters moved from the thesis' values and by how much,
// and the held-out comparison (mean+-sd over the held-out walks, failed walks); and its two
// pictures, the objective per generation and each held-out walk's objective, thesis against
// tuned (gnuplot, as the sweep engine draws).
#include <string>
#include <vector>

#include "console/tune/tune_output.hpp"
#include "console/tune/tune_run.hpp"

namespace stride::tune {

std::string report_text(const TuneSpec& tune, const TuneResult& result);

// search.csv-derived generation.csv + search.png, heldout_walks.csv + heldout.png (PNGs only
// when `png` and gnuplot is installed).
void write_tune_plots(const TuneOutput& output, const std::vector<SearchRecord>& records,
                      const TuneResult& result, bool png);

}  // namespace stride::tune
