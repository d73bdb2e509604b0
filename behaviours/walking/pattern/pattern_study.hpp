#pragma once
// The Ch. 3 pattern studied offline: sampled at a period with its leg joints, and what it does
// (how far and how fast it walks, its worst ZMP margin to the support polygon, the smallest
// support knee, the samples beyond the legs' reach). `stride pattern` prints and plots this.
#include <vector>

#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "behaviours/walking/pattern/pattern_parameters.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"

namespace stride::walking {

struct PatternFrame {
  PatternSample s;
  LegJoints q;
};

// The stretched-knee pattern, or the conventional one, every `dt` s from start to end.
std::vector<PatternFrame> sample_pattern(const PatternParameters& p, bool conventional, double dt);

struct PatternSummary {
  double duration = 0;          // s, the last sample's time
  double distance = 0;          // m, the waist's advance
  double worst_zmp_margin = 0;  // m, smallest ZMP margin to the support polygon
  double min_support_knee = 0;  // rad, smallest knee angle of a supporting leg
  int unreachable = 0;          // samples the leg IK clamped
};

// Needs at least one frame.
PatternSummary summarize_pattern(const std::vector<PatternFrame>& walk);

}  // namespace stride::walking
