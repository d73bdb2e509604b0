#pragma once
// `stride experiment kalman`: the TorsoStateEstimator during a hip-strategy walk with the
// walking parameters of Table 4.2, against the simulator's ground truth; then the Q/R sweeps of
// Figs. 4.1-4.2 rerun offline on the same IMU data (RMS error and lag per setting).
#include <iosfwd>

#include "console/experiments/experiment_options.hpp"

namespace stride::experiments {

int run_kalman_experiment(const ExperimentOptions& o, std::ostream& out);

}  // namespace stride::experiments
