#pragma once
// The Ch. 3 pattern re-planned on the way: a footstep moved (a stepping response to a push) and
// the rest of the walk carried along with it. The running plan is never rewritten: every change is
// a smooth offset blended in from the moment it is made, so the samples from then on start where
// the old plan was (samples before the latest change are not kept). The swing foot in flight is
// bent onto its new landing by the time it lands, the waist arrives over the moved walk by the same
// time, and the other foot follows in its next swing; from then on the walk is the original pattern
// moved by the sum of the changes.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "behaviours/walking/pattern/walking_pattern.hpp"

namespace stride::walking {

// An offset that goes from `from` to `to` over [t0, t1] (cosine: zero slope at both ends).
struct OffsetBlend {
  double t0 = 0, t1 = 0;
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
};

// The offset of a track at t: the last blend that has begun by t (zero before the first).
Eigen::Vector3d offset_at(const std::vector<OffsetBlend>& track, double t);

// What adjust_step() did.
struct StepAdjustment {
  int swing = -1;                                   // swing index moved
  Foot foot = Foot::kLeft;                          // the foot that swings there
  double start = 0, landing = 0;                    // s: when the change began, when it lands
  Eigen::Vector2d step = Eigen::Vector2d::Zero();   // m: how far that landing moved
  Eigen::Vector2d total = Eigen::Vector2d::Zero();  // m: the whole walk's offset afterwards
};

class AdjustedPattern {
 public:
  explicit AdjustedPattern(const PatternParameters& p);

  PatternSample sample(double t) const;
  double duration() const { return base_.duration(); }
  const StretchedKneePattern& base() const { return base_; }
  Eigen::Vector2d total_offset() const { return total_; }
  // Where foot f is planned at t: the original plan's place moved by the changes made so far.
  Eigen::Vector3d foot(Foot f, double t) const {
    return base_.footsteps().foot(f, t) + offset_at(feet_[index_of(f)], t);
  }

  // The swing in flight at `now` if it lands at least `min_time` later, else the next one.
  std::optional<int> swing_to_adjust(double now, double min_time) const;
  // Moves that swing's landing by `step` (x, y in the walk's frame) and the rest of the walk
  // with it; empty when no swing is left.
  std::optional<StepAdjustment> adjust_step(double now, const Eigen::Vector2d& step,
                                            double min_time);
  // Lowers the waist by `depth` over [now, now + down], holds it `hold`, and brings it back
  // over `up` (more reach for a recovery step from the stretched-knee pattern).
  void lower_waist(double now, double depth, double down, double hold, double up);

 private:
  static int index_of(Foot f) { return f == Foot::kLeft ? 0 : 1; }

  StretchedKneePattern base_;
  std::vector<OffsetBlend> feet_[2];  // left, right: x, y offsets (z unused)
  std::vector<OffsetBlend> waist_;    // x, y
  std::vector<OffsetBlend> height_;   // z
  Eigen::Vector2d total_ = Eigen::Vector2d::Zero();
};

}  // namespace stride::walking
