#pragma once
// One waist step of an online walk: [k T_step, (k+1) T_step) from the middle of one single support
// to the middle of the next, planned in the walk frame where it starts. Forward speed follows the
// thesis' profiles (Sec. 3.3.1: a rhythmic step when the speed is kept, a quartic when it
// changes), sideways speed and turn rate change by quartics with zero slope at both ends, the
// lateral sway is Eq. 3.7, Eq. 3.8, Eq. 3.9 and the height Eq. 3.10. Every quantity is continuous
// in position, velocity and acceleration across step boundaries when consecutive steps share their
// velocity.
#include "behaviours/walking/pattern/forward_motion.hpp"
#include "behaviours/walking/pattern/lateral_motion.hpp"
#include "behaviours/walking/pattern/motion_sample.hpp"
#include "behaviours/walking/pattern/pattern_parameters.hpp"
#include "behaviours/walking/steps/pose2.hpp"
#include "behaviours/walking/steps/step_velocity.hpp"

namespace stride::walking {

enum class StepKind { kFirst, kMiddle, kLast };

// The speed level (V_min, V_max) whose rhythmic step (Eq. 3.1) averages `mean` m/s, with the
// speed swing V_max - V_min in the same proportion to the mean as in `p.rhythmic`.
SpeedLevel level_for_mean_speed(const PatternParameters& p, double mean);

// The walk frame's motion within a step, in the frame where the step started.
struct LocalMotion {
  Motion1d forward, sideways, heading;  // heading.p: yaw turned since the step started
  Motion1d sway;                        // lateral waist offset from the walk frame (Eq. 3.9)
  Motion1d height;                      // torso-origin height (Eq. 3.10)
};

class WaistStep {
 public:
  // Step `index` from velocity `from` to `to` (a first step starts at rest, a last one ends at
  // rest) starting in the walk frame `start`.
  WaistStep(const PatternParameters& p, int index, StepKind kind, const StepVelocity& from,
            const StepVelocity& to, const Pose2& start);

  LocalMotion local(double u) const;  // u in [0, T_step]
  Pose2 frame_at(double u) const;     // the walk frame, integrated from the step's start
  const Pose2& start() const { return start_; }
  const Pose2& end() const { return end_; }
  const StepVelocity& to() const { return to_; }
  StepKind kind() const { return kind_; }
  int index() const { return index_; }

 private:
  Motion1d forward(double u) const;
  Motion1d sway(double u) const;

  double T_, T_s_, T_d_, A_l_, omega_, z_min_, z_max_;
  int index_;
  StepKind kind_;
  StepVelocity to_;
  bool rhythmic_ = false;
  SpeedLevel level_;
  VelocityQuartic forward_quartic_, sideways_, turn_;
  FirstStepCubic first_;
  Pose2 start_, end_;
};

}  // namespace stride::walking
