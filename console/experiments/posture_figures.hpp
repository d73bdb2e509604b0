#pragma once
// Figs. 4.6-4.12 from the posture sweep's traces (seed 1 of each case), one folder per figure
// family so a family's cases sit side by side:
//   <out>/figures/joint_angles/<case>.png       (a) reference and modified hip or ankle angles
//   <out>/figures/torso_inclination/<case>.png  (b) Kalman estimate, ground truth drawn last
//   <out>/figures/waist_velocity/<case>.png     (c) planned and true waist velocity
//   <out>/figures/zmp_world/<case>.png          (d) measured CoP, planned ZMP, true feet midpoint
//   <out>/figures/zmp_feet_frame/<case>.png     (e) both laterally from their own feet midpoint
// each with its gnuplot script (.gp) beside it.
#include <string>
#include <vector>

#include "console/sweep/sweep_engine.hpp"

namespace stride::experiments {

// The family folders under <out>/figures, in the order above.
const std::vector<std::string>& posture_figure_families();

// Figures of one case from its trace CSV (columns of posture.sweep.xml's <trace>; the feet and
// yaw columns are optional: without them the feet-frame figure is left out). Throws
// stride::Error when the trace cannot be read or gnuplot fails.
void write_posture_case_figures(const std::string& out_dir, const std::string& trace_csv,
                                const std::string& case_name, const std::string& figure);

// Every traced case of the sweep's result. Throws stride::Error when gnuplot fails on a trace.
void write_posture_figures(const std::string& out_dir, const sweep::SweepResult& result, bool png);

}  // namespace stride::experiments
