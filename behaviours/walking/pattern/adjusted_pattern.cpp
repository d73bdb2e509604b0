#include "behaviours/walking/pattern/adjusted_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stride::walking {

namespace {

double cosine_blend(double s) {
  return 0.5 - 0.5 * std::cos(std::numbers::pi * std::clamp(s, 0.0, 1.0));
}

Eigen::Vector3d planar(const Eigen::Vector2d& v) {
  return {v.x(), v.y(), 0.0};
}

// Drops the blends that have not begun by `now` (a new plan replaces what was still to come) and
// those before the last begun one, which no sample from `now` on reads: a track stays short.
void forget_future(std::vector<OffsetBlend>& track, double now) {
  track.erase(std::remove_if(track.begin(), track.end(),
                             [now](const OffsetBlend& b) { return b.t0 > now; }),
              track.end());
  if (track.size() > 1) track.erase(track.begin(), track.end() - 1);
}

}  // namespace

Eigen::Vector3d offset_at(const std::vector<OffsetBlend>& track, double t) {
  const OffsetBlend* last = nullptr;
  for (const OffsetBlend& b : track)
    if (b.t0 <= t) last = &b;
  if (!last) return Eigen::Vector3d::Zero();
  if (t >= last->t1) return last->to;
  return last->from +
         cosine_blend((t - last->t0) / (last->t1 - last->t0)) * (last->to - last->from);
}

AdjustedPattern::AdjustedPattern(const PatternParameters& p) : base_(p) {
  // At most one begun blend and two to come per track (forget_future): no allocation later.
  for (auto* track : {&feet_[0], &feet_[1], &waist_, &height_}) track->reserve(4);
}

PatternSample AdjustedPattern::sample(double t) const {
  PatternSample s = base_.sample(t);
  const Eigen::Vector3d waist = offset_at(waist_, t) + offset_at(height_, t);
  s.waist += waist;
  s.left_foot += offset_at(feet_[0], t);
  s.right_foot += offset_at(feet_[1], t);
  s.zmp += waist.head<2>();
  return s;
}

std::optional<int> AdjustedPattern::swing_to_adjust(double now, double min_time) const {
  const Footsteps& f = base_.footsteps();
  const int last = f.swings() - 1;
  const double T = base_.parameters().T_step();
  for (int j = std::max(0, static_cast<int>(std::floor(now / T)) - 1); j <= last; ++j)
    if (f.swing_end(j) - std::max(now, f.swing_start(j)) >= min_time && f.swing_end(j) > now)
      return j;
  return std::nullopt;
}

std::optional<StepAdjustment> AdjustedPattern::adjust_step(double now, const Eigen::Vector2d& step,
                                                           double min_time) {
  const auto j = swing_to_adjust(now, min_time);
  if (!j) return std::nullopt;
  const Footsteps& f = base_.footsteps();
  StepAdjustment a;
  a.swing = *j;
  a.foot = Footsteps::swing_foot(*j);
  a.start = std::max(now, f.swing_start(*j));
  a.landing = f.swing_end(*j);
  a.step = step;
  a.total = total_ + step;
  // The swing foot: from wherever it is (perhaps mid-blend) onto the moved landing.
  auto& swing = feet_[index_of(a.foot)];
  forget_future(swing, now);
  swing.push_back({a.start, a.landing, offset_at(swing, a.start), planar(a.total)});
  // The other foot follows in its next swing, if the walk has one left.
  auto& other = feet_[1 - index_of(a.foot)];
  forget_future(other, now);
  if (*j + 1 < f.swings()) {
    const double t0 = f.swing_start(*j + 1), t1 = f.swing_end(*j + 1);
    other.push_back({t0, t1, offset_at(other, t0), planar(a.total)});
  }
  // The waist arrives over the moved walk when the foot lands; its height is lower_waist()'s.
  forget_future(waist_, now);
  waist_.push_back({now, a.landing, offset_at(waist_, now), planar(a.total)});
  total_ = a.total;
  return a;
}

void AdjustedPattern::lower_waist(double now, double depth, double down, double hold, double up) {
  const Eigen::Vector3d low(0, 0, -depth);
  forget_future(height_, now);
  height_.push_back({now, now + down, offset_at(height_, now), low});
  height_.push_back({now + down + hold, now + down + hold + up, low, Eigen::Vector3d::Zero()});
}

}  // namespace stride::walking
