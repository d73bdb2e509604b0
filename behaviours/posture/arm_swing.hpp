#pragma once
// Yaw moment compensation by arm swing (thesis Sec. 4.4): a 4-mass model (upper body, swing
// leg, two arms) about the support foot centre O. Arms move reciprocally: the arm on the swing
// leg's side moves opposite to the swing leg, the other arm with it, so both arms' moments
// oppose the swing leg's.
#include <Eigen/Core>

namespace stride::behaviours {

struct ArmSwingModel {
  double swing_leg_mass = 0;         // m_s, kg
  double swing_side_arm_mass = 0;    // m_ar: arm at d0 + d1 from O
  double support_side_arm_mass = 0;  // m_al: arm at d1 - d0 from O
  double foot_half_distance = 0;     // d_0, m (half the distance between the legs)
  double arm_half_distance = 0;      // d_1, m (half the distance between the arms)
  double arm_com_distance = 0;       // d_a, m (shoulder joint to arm CoM)
};

// Yaw moment (Eq. 4.18) about O from the swing leg, the upper body (mass m_b at distance d) and
// the arms, each from its forward acceleration.
double support_yaw_moment(const ArmSwingModel& m, double swing_leg_acc, double body_mass,
                          double body_acc, double body_distance, double arm_acc);

// The arm acceleration of Eq. 4.19 with the body term neglected, integrated twice (Eq. 4.20):
// x_a = gain * x_s.
double arm_displacement_gain(const ArmSwingModel& m);

// The shoulder pitch angle (Eq. 4.21) that moves the arm CoM forward by x_a (asin argument
// clamped to [-1, 1]); forward arm motion is a negative change of the robot's shoulder pitch.
double arm_swing_angle(double arm_displacement, double arm_com_distance);

struct ArmSwingOffsets {
  double left_displacement = 0;  // arm CoM forward displacement, m
  double right_displacement = 0;
  double left_shoulder_pitch = 0;  // change of the robot's shoulder pitch, rad
  double right_shoulder_pitch = 0;
};

// Arm motion from the feet's forward positions in the torso frame. The swing leg's x_s is taken
// from the feet's midpoint, so it runs symmetrically through zero each step and one formula
// holds for either swing leg: each arm moves against its own leg.
ArmSwingOffsets arm_swing_offsets(const ArmSwingModel& m, double left_foot_x, double right_foot_x);

}  // namespace stride::behaviours
