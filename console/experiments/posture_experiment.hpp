#pragma once
// `stride experiment posture`: Sec. 4.3.4.2 — hip strategy, ankle strategy and no posture control
// at the low, medium and high speed settings on the floor with local unevenness (15 s walks),
// with the thesis' printed distance, speed and step length next to ours, and Figs. 4.6-4.12 as
// CSV + PNG (reference vs modified angles, torso inclination, waist velocity, measured ZMP).
#include <iosfwd>
#include <string>
#include <vector>

#include "console/experiments/experiment_options.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

// One scene of scenes/experiments and what the thesis printed for it (NaN: not printed).
struct PostureCase {
  std::string scene;                                  // e.g. "hip_medium"
  std::string figure;                                 // e.g. "Fig. 4.7"
  double thesis_distance, thesis_speed, thesis_step;  // m, m/s, m in 15 s
};
const std::vector<PostureCase>& posture_cases();

// Indices into posture_cases() that `selection` names (a scene, or a strategy prefix such as
// "hip"), in table order; all of them when it is empty. Throws stride::Error on a name that
// matches no case.
std::vector<std::size_t> selected_posture_cases(const std::vector<std::string>& selection);

// The four panels of Figs. 4.6-4.12 for one recorded walk, written as <stem>_*.csv/.png.
void write_walk_figures(const ExperimentOptions& o, const WalkRecording& r, const std::string& stem,
                        const std::string& title, bool ankle_joints);

int run_posture_experiment(const ExperimentOptions& o, std::ostream& out);

}  // namespace stride::experiments
