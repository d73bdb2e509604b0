#include "console/cli/ensemble_arguments.hpp"

#include "console/sweep/executor.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {

sim::EnsembleSpec read_ensemble_spec(ArgumentReader& a, const std::string& command, int members) {
  sim::EnsembleSpec spec;
  spec.members = members;
  if (a.has("--seed")) spec.first_seed = a.unsigned_integer("--seed");
  spec.heading_spread = a.number_or("--heading-spread", spec.heading_spread);
  if (!(spec.heading_spread >= 0 && spec.heading_spread <= 0.5))
    throw UsageError("stride " + command + ": --heading-spread: expected 0 to 0.5 rad");
  spec.position_spread = a.number_or("--position-spread", spec.position_spread);
  if (!(spec.position_spread >= 0 && spec.position_spread <= 0.5))
    throw UsageError("stride " + command + ": --position-spread: expected 0 to 0.5 m");
  return spec;
}

int read_jobs(ArgumentReader& a, const std::string& command) {
  if (!a.has("--jobs")) return sweep::hardware_jobs();
  const std::uint64_t n = a.unsigned_integer("--jobs");
  if (n < 1 || n > 256) throw UsageError("stride " + command + ": --jobs: expected 1..256");
  return static_cast<int>(n);
}

}  // namespace stride::cli
