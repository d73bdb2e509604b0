#pragma once
// `stride experiment gains`: each strategy's PD gains swept one at a time around its medium-speed
// figure's (hip: Fig. 4.7, K_p = 0.40, K_d = -0.05; ankle: Fig. 4.11, K_p = 0.28, K_d = -0.06) on
// the uneven floor, to set against Sec. 4.3.4.2's remarks: the torso leans back as K_p rises,
// oscillates when K_p is too large, shakes at K_d <= -0.06.
#include <cstdint>
#include <iosfwd>
#include <string>

#include "console/experiments/experiment_options.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

int run_gains_experiment(const ExperimentOptions& o, std::ostream& out);

// One walk of it: <strategy>_medium ("hip" or "ankle") with both pitch and roll gains (kp, kd).
WalkSetup gains_walk(const ExperimentOptions& o, const std::string& strategy, double kp, double kd,
                     std::uint64_t seed);

}  // namespace stride::experiments
