#pragma once
// The named Chapter 4 experiments behind `stride experiment <name>`.
#include <iosfwd>
#include <string>

#include "console/experiments/experiment_options.hpp"

namespace stride::experiments {

// "posture, knee-energy, kalman, fastest, arm-swing"
std::string experiment_names();

// Runs one by name and prints its table; the exit code (0 ok, 2 when a walk that should be
// stable fell). Throws stride::Error for an unknown name, listing the known ones.
int run_experiment(const std::string& name, const ExperimentOptions& o, std::ostream& out);

}  // namespace stride::experiments
