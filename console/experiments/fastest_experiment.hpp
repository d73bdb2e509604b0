#pragma once
// `stride experiment fastest`: the fastest stable walk. From the high-speed setting of
// Sec. 4.3.4.2 (0.24 m/s) the rhythmic speed is raised in steps; at each speed a short list of
// settings (T_stride, waist height, step height, posture gains) is tried in order until one walks
// the whole way without falling; the search ends at the first speed where none does.
#include <iosfwd>
#include <string>
#include <vector>

#include "console/experiments/experiment_options.hpp"

namespace stride::experiments {

// One setting tried at a target speed: PatternWalk, HipStrategy and ArmSwing parameters.
struct FastWalkSetting {
  double T_stride, z_min, z_max, H_foot, kp, kd;
  double arm_swing;      // ArmSwing gain_scale: Sec. 4.4's yaw-moment compensation on (1) or off
  const char* strategy;  // the PostureCorrectedRequest provider: HipStrategy or AnkleStrategy
};
const std::vector<FastWalkSetting>& fast_walk_settings();

// PatternWalk's parameter text for a rhythmic speed v (V_min = v - 0.005, V_max = v + 0.005).
std::string fast_walk_parameters(const FastWalkSetting& s, double v);

int run_fastest_experiment(const ExperimentOptions& o, std::ostream& out);

}  // namespace stride::experiments
