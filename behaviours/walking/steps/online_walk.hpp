#pragma once
// The thesis' walking pattern (Ch. 3) planned online, one step at a time, from a velocity request:
// each waist step's speed, sideways speed and turn rate are chosen when the swing that ends it
// lifts off (the step's footholds are then fixed), from the request at that moment within the
// StepLimits; a step whose leg IK would leave the joint limits or the legs' reach is planned again
// with half its change. The walk starts from standing with a first step (Eq. 3.6, Eq. 3.7, Eq. 3.8)
// and, once asked to stand and slow enough, ends with a last step that brings the waist to rest
// between the feet.
//
// Footholds: at boundary j the support foot (left at odd j) stands d_0 beside the walk frame
// F_j, turned with it (Eq. 3.12 on a path); swing j carries the other foot from foothold j-1 to
// j+1 along the cycloid of Eq. 3.11, its sideways move and yaw early in the swing. The torso yaws
// midway between the feet, the only orientation the shared HipYawPitch reaches with both feet.
#include <deque>
#include <span>

#include <Eigen/Core>

#include "behaviours/walking/pattern/footsteps.hpp"
#include "behaviours/walking/steps/waist_step.hpp"

namespace stride::walking {

struct FootPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // sole-frame origin, world
  double yaw = 0.0;
};

// The pattern at one instant; frame: the world frame of the walk's origin (x forward, y left).
struct WalkSample {
  double t = 0.0;         // walk time
  Pose2 frame;            // the walk frame (the plan's odometry)
  Pose2 reference;        // where the granted requests alone put it (no heading correction)
  StepVelocity velocity;  // the walk frame's, in its own axes
  Eigen::Vector3d waist = Eigen::Vector3d::Zero();  // torso origin
  Eigen::Vector3d waist_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d waist_acceleration = Eigen::Vector3d::Zero();
  double torso_yaw = 0.0;
  FootPose left, right;
  SupportPhase support = SupportPhase::kDouble;
  Eigen::Vector2d zmp = Eigen::Vector2d::Zero();  // the ZMP of Eq. 3.16
  int step = -1;                                  // waist step under way (-1 standing)
};

// Where a swing not yet ended will put its foot.
struct Landing {
  Foot foot = Foot::kLeft;
  FootPose pose;
};

class OnlineWalk {
 public:
  // Measured: scenes/experiments/README.md "walk requests".
  static constexpr double kEarlyShare = 0.5;

  // Standing at `at` (the walk frame; feet d_0 either side), the reference path continuing from
  // `reference`; p and limits are validated (throws Error).
  // A swinging foot makes its sideways move and its turn within the first `early_share` of its
  // swing (0.1 to 1; 1: along its cycloid like its forward move).
  OnlineWalk(const PatternParameters& p, const StepLimits& limits, const Pose2& at,
             const Pose2& reference, double early_share = kEarlyShare);

  // Plans every step whose lift-off is at or before walk time `t` from the request then:
  // `walk` false asks to stop. `correction` is added to the granted velocity of the steps planned
  // but not to the reference path (a heading and place hold makes up for the feet turning and
  // sliding on the floor): its turn beyond the limits' range, its forward and sideways speed
  // within it. Times only go forward.
  void advance(double t, bool walk, const StepVelocity& wanted,
               const StepVelocity& correction = {});
  WalkSample sample(double t) const;
  // The planned landings of the swings that end after `t`, soonest first, at most out.size().
  int landings_after(double t, std::span<Landing> out) const;

  // True once the last step has been planned, and after it ended.
  bool stopping() const { return steps_total_ > 0; }
  bool ended(double t) const { return stopping() && t >= steps_total_ * T_; }
  // The velocity granted for the latest planned step (its end), and the request it answered
  // before the limits (clamped to the range only).
  const StepVelocity& granted() const { return granted_; }
  const StepVelocity& wanted_in_range() const { return wanted_in_range_; }
  int planned_steps() const { return next_step_; }
  // Plans redone with half their change because the leg IK left the limits or the legs' reach.
  int shortened() const { return shortened_; }
  const PatternParameters& parameters() const { return p_; }
  void set_limits(const StepLimits& limits) { limits_ = limits; }

 private:
  void plan(bool walk, const StepVelocity& wanted, const StepVelocity& correction);
  double decision_time(int k) const { return k == 0 ? 0.0 : k * T_ - T_s_; }
  const WaistStep& step(int k) const;
  bool within_reach(int k) const;  // the leg IK until step k+1 is planned
  Pose2 foothold(int j) const;
  FootPose foot(Foot f, double t) const;
  FootPose foot_at(Foot f, int j) const;  // standing at foothold j
  double swing_start(int j) const;
  double swing_end(int j) const;
  SupportPhase support(double t) const;

  PatternParameters p_;
  StepLimits limits_;
  double T_, T_s_;
  Pose2 origin_;
  std::deque<WaistStep> steps_;      // the last few planned steps
  std::deque<WaistStep> reference_;  // the same steps at the granted velocities alone
  Pose2 reference_origin_;
  int first_kept_ = 0;   // index of steps_.front()
  int next_step_ = 0;    // steps planned so far
  int steps_total_ = 0;  // N once the last step is planned, else 0
  int shortened_ = 0;
  double early_share_;
  StepVelocity granted_, wanted_in_range_;
};

}  // namespace stride::walking
