#pragma once
// A heading hold for the thesis' straight pattern (Ch. 3, PatternWalk): the pattern is played in
// a frame that turns about the support foot while the other foot swings, by at most
// `max_per_step` a step, so that the walk turns back to the heading it started with; the swing
// foot turns with the frame and lands on its heading, the support foot keeps the yaw it landed
// with, and the torso is yawed where the shared HipYawPitch reaches both (model::legs_ik_turned).
// The heading is the measured torso yaw (WalkOdometry) less the yaw the legs put between the
// torso and the frame, averaged over the last two steps (the gait swings the torso's yaw).
#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "behaviours/walking/steps/pose2.hpp"

namespace stride::walking {

struct HeadingHoldSettings {
  double gain = 0.0;            // share of the measured heading turned back in one step
  double max_per_step = 0.1;    // rad a step at most
  double single_support = 0.0;  // s, the pattern's single-support time (2 T_s)
};

struct HeldJoints {
  LegJoints legs;
  double torso_yaw = 0.0;  // of the frame's world, as the IK put it
};

class HeadingHold {
 public:
  // Pattern time t, the pattern's sample then and the torso's measured yaw.
  HeldJoints joints(const PatternSample& s, double t, double measured_yaw,
                    const HeadingHoldSettings& settings);
  const Pose2& frame() const { return frame_; }

 private:
  void start_swing(const PatternSample& s, double t, const HeadingHoldSettings& settings);
  void turn_frame(double share);  // the frame turned by share of this swing's turn
  Eigen::Vector3d in_frame(const Eigen::Vector3d& p) const;

  Pose2 frame_, from_;
  Eigen::Vector2d pivot_ = Eigen::Vector2d::Zero();
  double turn_ = 0.0, swing_start_ = 0.0, share_ = 0.0;
  double planted_yaw_[2] = {0.0, 0.0};  // left, right
  double torso_yaw_ = 0.0;
  double heading_sum_ = 0.0, step_mean_before_ = 0.0;  // the measured heading, step by step
  int frames_ = 0, frames_before_ = 0;
  SupportPhase support_ = SupportPhase::kDouble;
};

}  // namespace stride::walking
