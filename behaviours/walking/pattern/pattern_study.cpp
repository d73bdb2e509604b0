#include "behaviours/walking/pattern/pattern_study.hpp"

#include <algorithm>
#include <limits>

#include "behaviours/walking/pattern/support_polygon.hpp"

namespace stride::walking {

std::vector<PatternFrame> sample_pattern(const PatternParameters& p, bool conventional, double dt) {
  const std::vector<PatternSample> samples = conventional
                                                 ? sample_walk(ConventionalPattern(p), dt)
                                                 : sample_walk(StretchedKneePattern(p), dt);
  std::vector<PatternFrame> walk;
  walk.reserve(samples.size());
  for (const PatternSample& s : samples) walk.push_back({s, leg_joints(s)});
  return walk;
}

PatternSummary summarize_pattern(const std::vector<PatternFrame>& walk) {
  PatternSummary r;
  double worst = std::numeric_limits<double>::infinity(), min_knee = worst;
  for (const PatternFrame& f : walk) {
    worst = std::min(worst, zmp_margin(f.s));
    r.unreachable += f.q.reachable ? 0 : 1;
    if (f.s.support == SupportPhase::kLeft) min_knee = std::min(min_knee, f.q.left[3]);
    if (f.s.support == SupportPhase::kRight) min_knee = std::min(min_knee, f.q.right[3]);
  }
  r.worst_zmp_margin = worst;
  r.min_support_knee = min_knee;
  r.duration = walk.back().s.t;
  r.distance = walk.back().s.waist.x();
  return r;
}

}  // namespace stride::walking
