#pragma once
// `stride experiment arm-swing`: Fig. 4.18 — the compensating shoulder pitch angles of Sec. 4.4
// during 20 s (81-step) walks with T_stride = 0.5 s and A_l = 1 mm at the three printed speeds.
#include <iosfwd>

#include "console/experiments/experiment_options.hpp"

namespace stride::experiments {

int run_arm_swing_experiment(const ExperimentOptions& o, std::ostream& out);

}  // namespace stride::experiments
