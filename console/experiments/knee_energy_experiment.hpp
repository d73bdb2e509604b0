#pragma once
// `stride experiment knee-energy`: Sec. 4.3.4.3 — 20 s walks at about 0.05, 0.10, 0.15 and
// 0.20 m/s with the stretched-knee pattern (Table 4.4) and the conventional constant-height
// pattern (Table 4.5), repeated over noise seeds; electrical energy of both knee actuators from
// the simulated currents (Eqs. 4.16-4.17), mean +- std, the saving in percent, Figs. 4.13-4.15.
#include <iosfwd>
#include <span>

#include "console/experiments/experiment_options.hpp"
#include "console/experiments/knee_energy.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

struct KneeEnergy {
  double left = 0, right = 0;  // J
  int samples = 0;             // control frames summed (the thesis: 2000 in 20 s)
};

// Eq. 4.16 for both knees over the walking part of a recorded trace (0 <= pattern_t < duration).
KneeEnergy knee_energy(const WalkRecording& r, double voltage = kNominalArmatureVoltage);

int run_knee_energy_experiment(const ExperimentOptions& o, std::ostream& out);

}  // namespace stride::experiments
