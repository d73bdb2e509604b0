#pragma once
// Torso pitch/roll PD correction of the walking joint targets (thesis Sec. 4.3.3): the same PD
// law drives either the hip joints (hip strategy) or the ankle joints (ankle strategy).
//
// Sign convention. The thesis writes the correction with the error desired - measured and
// positive K_p. In the robot's convention (torso pitch > 0 leans forward, roll > 0 leans right;
// every pitch axis along +y and every roll axis along +x), with the feet flat the torso angle is
// minus the sum of the leg's joint angles about that axis (hip + knee + ankle pitch, or hip +
// ankle roll). A forward lean is therefore undone by increasing hip or ankle pitch, so the thesis'
// correction enters the joints negated: q_mod = q_ref - Delta (kJointSignOfCorrection).
#include <array>

#include <Eigen/Core>

#include "robot/hal/joint_id.hpp"

namespace stride::behaviours {

inline constexpr double kJointSignOfCorrection = -1.0;

struct PostureGains {
  double kp_pitch = 0;  // K_p1
  double kd_pitch = 0;  // K_d1, s
  double kp_roll = 0;   // K_p2
  double kd_roll = 0;   // K_d2, s
};

// Desired or measured torso state in the order of Eq. 4.5: [pitch, roll, pitch_rate, roll_rate].
// Returns (Delta theta, Delta phi) of Eqs. 4.8-4.9 (hip) = Eqs. 4.12-4.13 (ankle), thesis sign.
Eigen::Vector2d posture_correction(const PostureGains& gains, const Eigen::Vector4d& desired,
                                   const Eigen::Vector4d& measured);

enum class PostureJoints { Hip, Ankle };

// Eqs. 4.10-4.11 (hip) or 4.14-4.15 (ankle): adds the correction to both legs' pitch and roll
// joints of `position` (LoLA order), in the robot's sign (see above).
void apply_posture_correction(PostureJoints joints, const Eigen::Vector2d& correction,
                              std::array<double, hal::kNumJoints>& position);

}  // namespace stride::behaviours
