#pragma once
// The perturbed-start flags `stride run --ensemble` and `stride converge` share:
// [--seed N] [--heading-spread rad] [--position-spread m] [--jobs N].
#include <string>

#include "console/cli/arguments.hpp"
#include "simulator/scene/start_perturbation.hpp"

namespace stride::cli {

// An ensemble of `members` starts from the flags (defaults: sim::EnsembleSpec's).
sim::EnsembleSpec read_ensemble_spec(ArgumentReader& a, const std::string& command, int members);
// --jobs N (1..256), default: the machine's hardware threads.
int read_jobs(ArgumentReader& a, const std::string& command);

}  // namespace stride::cli
