#pragma once
// Torso pitch/roll PD correction of the walking joint targets (thesis Sec. 4.3.3): the same PD
// law drives either the hip joints (hip strategy) or the ankle joints (ankle strategy).
//
// Sign convention. Our joint signs are NAOqi's, which the thesis' App. B kinematics uses too; its
// IMU signs are not printed and are read as NAOqi's, also ours (torso pitch > 0 leans forward,
// roll > 0 leans right, gyro = time derivative of those angles). So the corrections enter the
// joints as printed, q_mod = q_ref + Delta, with the thesis' gains K_p > 0, K_d < 0. Read in these
// signs, the P term turns the hip (or ankle) with the lean (over a flat foot a forward lean tilts
// the torso further forward by K_p * pitch: the hip bends into the fall and the ankle levels a
// rolling foot), and the D term opposes the lean's rate. The opposite reading (q_mod = q_ref -
// Delta, "push the torso upright") made the printed K_d anti-damp and, with the ankle, fell in 17
// of 18 walks (K_p = 0.30, 3 speeds x 2 K_d x 3 seeds).
#include <array>

#include <Eigen/Core>

#include "robot/hal/joint_id.hpp"

namespace stride::behaviours {

inline constexpr double kJointSignOfCorrection = 1.0;  // the + of Eq. 4.10 and the others

struct PostureGains {
  double kp_pitch = 0;  // K_p1
  double kd_pitch = 0;  // K_d1, s
  double kp_roll = 0;   // K_p2
  double kd_roll = 0;   // K_d2, s
};

// Desired or measured torso state in the order of Eq. 4.5: [pitch, roll, pitch_rate, roll_rate].
// Returns (Delta theta, Delta phi) of Eq. 4.8 and Eq. 4.9 (hip), the same as the ankle's
// Eq. 4.12 and Eq. 4.13, thesis sign.
Eigen::Vector2d posture_correction(const PostureGains& gains, const Eigen::Vector4d& desired,
                                   const Eigen::Vector4d& measured);

enum class PostureJoints { Hip, Ankle };

// Adds the correction to both legs' pitch and roll joints of `position` (LoLA order): Eq. 4.10
// and Eq. 4.11 (hip) or Eq. 4.14 and Eq. 4.15 (ankle).
void apply_posture_correction(PostureJoints joints, const Eigen::Vector2d& correction,
                              std::array<double, hal::kNumJoints>& position);

}  // namespace stride::behaviours
