#include "behaviours/walking/steps/heading_hold.hpp"

#include <algorithm>

#include "behaviours/walking/pattern/footsteps.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"

namespace stride::walking {

Eigen::Vector3d HeadingHold::in_frame(const Eigen::Vector3d& p) const {
  const Eigen::Vector2d xy = point_in(frame_, p.x(), p.y());
  return {xy.x(), xy.y(), p.z()};
}

void HeadingHold::start_swing(const PatternSample& s, double t,
                              const HeadingHoldSettings& settings) {
  const bool left_supports = s.support == SupportPhase::kLeft;
  pivot_ = in_frame(left_supports ? s.left_foot : s.right_foot).head<2>();
  from_ = frame_;
  swing_start_ = t;
  // The heading over the last two steps: the gait's own yaw swing, left and right, cancels.
  const double step_mean = frames_ > 0 ? heading_sum_ / frames_ : 0.0;
  const double heading = frames_before_ > 0 ? 0.5 * (step_mean + step_mean_before_) : step_mean;
  step_mean_before_ = step_mean;
  frames_before_ = frames_;
  heading_sum_ = 0.0;
  frames_ = 0;
  turn_ = std::clamp(-settings.gain * heading, -settings.max_per_step, settings.max_per_step);
}

void HeadingHold::turn_frame(double share) {
  share_ = share;
  const double a = share_ * turn_;
  const Eigen::Vector2d xy = pivot_ + rotated(a, from_.x - pivot_.x(), from_.y - pivot_.y());
  frame_ = {xy.x(), xy.y(), from_.yaw + a};
}

HeldJoints HeadingHold::joints(const PatternSample& s, double t, double measured_yaw,
                               const HeadingHoldSettings& settings) {
  const auto single = [](SupportPhase p) {
    return p == SupportPhase::kLeft || p == SupportPhase::kRight;
  };
  // The frame's heading in the world: the measured torso yaw less the torso's yaw in the frame.
  heading_sum_ += wrap_angle(measured_yaw - (torso_yaw_ - frame_.yaw));
  ++frames_;
  if (single(support_) && s.support != support_) {
    turn_frame(1.0);  // the swing ended: its foot stands on the turned frame's heading
    planted_yaw_[support_ == SupportPhase::kLeft ? 1 : 0] = frame_.yaw;
  }
  if (single(s.support) && s.support != support_) start_swing(s, t, settings);
  support_ = s.support;
  // The frame turns by the swing foot's cycloid share, so the turn starts and ends at rest.
  if (single(s.support))
    turn_frame(settings.single_support > 0.0
                   ? cycloid_share((t - swing_start_) / settings.single_support)
                   : 1.0);
  double yaw[2] = {planted_yaw_[0], planted_yaw_[1]};
  if (single(s.support)) {
    const int swing = s.support == SupportPhase::kLeft ? 1 : 0;
    yaw[swing] = planted_yaw_[swing] + share_ * (frame_.yaw - planted_yaw_[swing]);
  }
  const Eigen::Vector3d waist = in_frame(s.waist);
  const model::TurnedLegsIkResult ik = model::legs_ik_turned(
      in_frame(s.left_foot) - waist, yaw[0], in_frame(s.right_foot) - waist, yaw[1]);
  torso_yaw_ = ik.torso_yaw;
  const model::LegsIkResult& l = ik.legs;
  return {{l.left.q, l.right.q, l.left.reachable && l.right.reachable,
           static_cast<std::uint16_t>(l.left.beyond_limits | (l.right.beyond_limits << 6))},
          ik.torso_yaw};
}

}  // namespace stride::walking
