#pragma once
// `stride experiment gains`: the hip strategy's PD gains swept one at a time around Fig. 4.7's
// (K_p = 0.40, K_d = -0.05, medium speed, uneven floor), to set against Sec. 4.3.4.2's remarks:
// the torso leans back as K_p rises, oscillates when K_p is too large, shakes at K_d <= -0.06.
#include <cstdint>
#include <iosfwd>

#include "console/experiments/experiment_options.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

int run_gains_experiment(const ExperimentOptions& o, std::ostream& out);

// One walk of it: hip_medium with both pitch and roll gains set to (kp, kd).
WalkSetup gains_walk(const ExperimentOptions& o, double kp, double kd, std::uint64_t seed);

}  // namespace stride::experiments
