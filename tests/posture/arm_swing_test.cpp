// Sec. 4.4: yaw moment compensation by arm swing (Eqs. 4.18-4.21).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "behaviours/posture/arm_swing.hpp"
#include "behaviours/posture/posture_modules.hpp"

namespace stride::behaviours {
namespace {

TEST(ArmSwing, ArmMotionOfEquation420CancelsTheYawMoment) {
  // Unequal arm masses so both terms of the denominator matter.
  const ArmSwingModel m{0.9, 0.5, 0.7, 0.05, 0.1, 0.09};
  const double k = arm_displacement_gain(m);
  EXPECT_NEAR(k, 2 * 0.9 * 0.05 / (0.7 * 0.05 + 0.5 * 0.15), 1e-15);  // Eq. 4.20
  for (const double swing_acc : {-3.0, 0.5, 12.0}) {
    // x_a = k x_s, so the arm acceleration is k times the swing leg's (upper body neglected).
    EXPECT_NEAR(support_yaw_moment(m, swing_acc, 4.0, 0.0, 0.03, k * swing_acc), 0, 1e-14);
    // Without arms the swing leg leaves 2 m_s d0 a_s.
    EXPECT_NEAR(support_yaw_moment(m, swing_acc, 4.0, 0.0, 0.03, 0), 2 * 0.9 * 0.05 * swing_acc,
                1e-14);
  }
  // Eq. 4.18's body term: a body acceleration against the swing leg adds m_b a_b d.
  EXPECT_NEAR(support_yaw_moment(m, 0, 4.0, -2.0, 0.03, 0), 4.0 * 2.0 * 0.03, 1e-15);
}

TEST(ArmSwing, ShoulderAngleIsTheArcsineOfTheDisplacement) {
  const double da = 0.0952;
  EXPECT_NEAR(arm_swing_angle(da * std::sin(0.3), da), -0.3, 1e-12);  // Eq. 4.21, forward
  EXPECT_NEAR(arm_swing_angle(-da * std::sin(0.2), da), 0.2, 1e-12);  // backward
  EXPECT_EQ(arm_swing_angle(0, da), 0);
  EXPECT_NEAR(arm_swing_angle(5 * da, da), -std::numbers::pi / 2, 1e-15);  // clamped
}

TEST(ArmSwing, EachArmSwingsAgainstItsOwnLeg) {
  const ArmSwingModel m = ArmSwingParameters{}.model();
  const double step = 0.0479;  // Fig. 4.18 (bottom), average step length
  double left_leg_dot_arm = 0, left_leg_sq = 0, left_arm_sq = 0, peak = 0;
  for (int i = 0; i <= 100; ++i) {
    // Left leg swings from behind to ahead (cycloid), the right foot mirrors it about the waist.
    const double s = i / 100.0;
    const double left_x =
        step * (s - std::sin(2 * std::numbers::pi * s) / (2 * std::numbers::pi) - 0.5);
    const double right_x = -left_x;
    const ArmSwingOffsets o = arm_swing_offsets(m, left_x, right_x);
    EXPECT_NEAR(o.left_displacement, -o.right_displacement, 1e-15);
    EXPECT_NEAR(o.left_displacement, -arm_displacement_gain(m) * left_x, 1e-15);
    if (left_x > 1e-6) {
      EXPECT_LT(o.left_displacement, 0);     // swing-side arm goes back ...
      EXPECT_GT(o.left_shoulder_pitch, 0);   // ... which is more shoulder pitch on the NAO
      EXPECT_LT(o.right_shoulder_pitch, 0);  // the other arm comes forward
    }
    left_leg_dot_arm += left_x * o.left_displacement;
    left_leg_sq += left_x * left_x;
    left_arm_sq += o.left_displacement * o.left_displacement;
    peak = std::max(peak, std::abs(o.left_shoulder_pitch));
  }
  EXPECT_NEAR(left_leg_dot_arm / std::sqrt(left_leg_sq * left_arm_sq), -1.0, 1e-12);  // antiphase
  // NAO numbers: gain = 2 m_s d0 / (2 m_a d1), peak angle asin(gain * L/2 / d_a).
  const double gain = 2 * 0.8429 * 0.05 / (2 * 0.57858 * 0.098);
  EXPECT_NEAR(peak, std::asin(gain * step / 2 / 0.0952), 1e-12);
}

}  // namespace
}  // namespace stride::behaviours
