#pragma once
// Figs. 4.6-4.12 from the posture sweep's traces (seed 1 of each case): (a) reference and
// modified hip or ankle angles, (b) torso inclination, (c) waist velocity, (d) the measured ZMP
// against the planned one, as <out>/posture_<case>_<panel>.png next to the trace CSVs.
#include <string>

#include "console/sweep/sweep_engine.hpp"

namespace stride::experiments {

// Throws stride::Error when gnuplot fails on a trace.
void write_posture_figures(const std::string& out_dir, const sweep::SweepResult& result, bool png);

}  // namespace stride::experiments
