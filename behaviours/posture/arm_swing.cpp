#include "behaviours/posture/arm_swing.hpp"

#include <algorithm>
#include <cmath>

namespace stride::behaviours {

double support_yaw_moment(const ArmSwingModel& m, double swing_leg_acc, double body_mass,
                          double body_acc, double body_distance, double arm_acc) {
  const double d0 = m.foot_half_distance;
  const double d1 = m.arm_half_distance;
  return 2 * m.swing_leg_mass * d0 * swing_leg_acc - body_mass * body_acc * body_distance -
         m.swing_side_arm_mass * arm_acc * (d0 + d1) -
         m.support_side_arm_mass * arm_acc * (d1 - d0);  // Eq. 4.18
}

double arm_displacement_gain(const ArmSwingModel& m) {
  const double d0 = m.foot_half_distance;
  const double d1 = m.arm_half_distance;
  // Eq. 4.19 without the body term, integrated twice into the gain of Eq. 4.20
  return 2 * m.swing_leg_mass * d0 /
         (m.support_side_arm_mass * (d1 - d0) + m.swing_side_arm_mass * (d0 + d1));
}

double arm_swing_angle(double arm_displacement, double arm_com_distance) {
  return -std::asin(std::clamp(arm_displacement / arm_com_distance, -1.0, 1.0));  // Eq. 4.21
}

ArmSwingOffsets arm_swing_offsets(const ArmSwingModel& m, double left_foot_x, double right_foot_x) {
  const double k = arm_displacement_gain(m);
  ArmSwingOffsets o;
  o.left_displacement = k * (right_foot_x - left_foot_x) / 2;   // Eq. 4.20, x_s = left foot
  o.right_displacement = k * (left_foot_x - right_foot_x) / 2;  // Eq. 4.20, x_s = right foot
  o.left_shoulder_pitch = arm_swing_angle(o.left_displacement, m.arm_com_distance);
  o.right_shoulder_pitch = arm_swing_angle(o.right_displacement, m.arm_com_distance);
  return o;
}

}  // namespace stride::behaviours
