#pragma once
// The named Chapter 4 experiments behind `stride experiment <name>`: short names for the sweep
// files in scenes/experiments (posture, knee-energy, gains, fastest, arm-swing), run by the one
// sweep engine, and the Kalman study (one walk, its filter rerun offline).
#include <iosfwd>
#include <string>
#include <vector>

#include "console/experiments/experiment_options.hpp"
#include "console/sweep/sweep.hpp"

namespace stride::experiments {

// "posture, knee-energy, kalman, fastest, arm-swing, gains"
std::string experiment_names();

// The sweep file of a named experiment (<sweeps_dir>/<name>.sweep.xml), or "" for one that is
// no sweep (kalman). Throws stride::Error for an unknown name, listing the known ones.
std::string experiment_sweep_file(const std::string& name, const std::string& sweeps_dir);

// --cases of the posture study: each a level of the sweep's `case` column (hip_slow) or a
// strategy (hip: its three speeds); the levels in the order asked. Throws stride::Error naming
// an unknown case.
std::vector<std::string> posture_case_levels(const sweep::Sweep& posture,
                                             const std::vector<std::string>& cases);

// Runs one by name and prints its tables; the exit code (0 ok, 130 interrupted).
int run_experiment(const std::string& name, const ExperimentOptions& o, std::ostream& out,
                   std::ostream& err);

}  // namespace stride::experiments
