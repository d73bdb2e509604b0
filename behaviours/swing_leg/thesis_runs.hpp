#pragma once
// The four closed-loop studies of Sec. 5.4.1 with the thesis' references and gains: planar and
// 3-D swing leg, step response and trajectory tracking.
#include <string>
#include <vector>

#include "behaviours/swing_leg/tracking_simulation.hpp"

namespace stride::swing_leg {

struct ThesisRun {
  std::string name;         // planar-step, planar-track, 3d-step, 3d-track
  std::string figures;      // the thesis figures it corresponds to
  TrackingOptions options;  // controller left Adaptive; the PD comparison uses the same gains
  ReferenceFunction reference;
};

// Throws stride::Error naming the known runs.
ThesisRun thesis_run(const std::string& name);
std::vector<std::string> thesis_run_names();

// Constant desired angles (the step responses).
ReferenceFunction step_reference(const Eigen::VectorXd& target);
// The three sums of sines of the planar tracking study.
ReferenceFunction planar_sine_reference();
// The left leg's joints of the Ch. 3 pattern (preset `preset`), in the 3-D model's order
// [hip roll, hip pitch, knee, ankle pitch, ankle roll], derivatives by central differences.
ReferenceFunction walking_pattern_reference(const std::string& preset);

}  // namespace stride::swing_leg
