#pragma once
// The landing-control study's figure from its output (runs.csv and traces/): each traced walk's
// FSR totals of both soles over one second of walking, landing control off against on,
// as <out>/fsr_touchdown.png (and its CSV; fsr_touchdown_runs.csv one row per frame and walk).
#include <string>

namespace stride::experiments {

// Throws stride::Error when a file or column is missing or gnuplot fails; without `png` or
// gnuplot only the CSV is written, and nothing at all when no walk was traced.
void write_landing_figure(const std::string& out_dir, bool png);

}  // namespace stride::experiments
