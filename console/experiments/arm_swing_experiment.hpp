#pragma once
// `stride experiment arm-swing`: Fig. 4.18 — the compensating shoulder pitch angles of Sec. 4.4
// during 20 s (81-step) walks with T_stride = 0.5 s and A_l = 1 mm at the three printed speeds,
// and what the swing is for: the same walks with and without it, the support foot's yaw turn.
#include <cstdint>
#include <iosfwd>

#include "console/experiments/experiment_options.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

int run_arm_swing_experiment(const ExperimentOptions& o, std::ostream& out);

// One walk of it: hip strategy on the uneven floor, 80 waist steps, A_l = 1 mm, at about
// `target_speed`, with the swing of Eq. 4.20 on or off.
WalkSetup arm_swing_walk(const ExperimentOptions& o, double target_speed, bool swing,
                         std::uint64_t seed);

}  // namespace stride::experiments
