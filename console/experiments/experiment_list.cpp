#include "console/experiments/experiment_list.hpp"

#include <array>
#include <ostream>

#include "console/experiments/arm_swing_experiment.hpp"
#include "console/experiments/fastest_experiment.hpp"
#include "console/experiments/gains_experiment.hpp"
#include "console/experiments/kalman_experiment.hpp"
#include "console/experiments/knee_energy_experiment.hpp"
#include "console/experiments/posture_experiment.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

struct Entry {
  const char* name;
  int (*run)(const ExperimentOptions&, std::ostream&);
};
constexpr std::array kExperiments = {
    Entry{"posture", run_posture_experiment},     Entry{"knee-energy", run_knee_energy_experiment},
    Entry{"kalman", run_kalman_experiment},       Entry{"fastest", run_fastest_experiment},
    Entry{"arm-swing", run_arm_swing_experiment}, Entry{"gains", run_gains_experiment},
};

}  // namespace

std::string experiment_names() {
  std::string names;
  for (const Entry& e : kExperiments) names += (names.empty() ? "" : ", ") + std::string(e.name);
  return names;
}

int run_experiment(const std::string& name, const ExperimentOptions& o, std::ostream& out) {
  for (const Entry& e : kExperiments)
    if (name == e.name) return e.run(o, out);
  throw Error("stride experiment: unknown experiment '" + name + "' (expected one of " +
              experiment_names() + ")");
}

}  // namespace stride::experiments
