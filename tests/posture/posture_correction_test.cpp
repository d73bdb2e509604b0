// Sec. 4.3.3: hip and ankle strategies (Eqs. 4.8-4.15) and their sign on the robot.
#include <gtest/gtest.h>

#include <cmath>

#include "behaviours/posture/posture_correction.hpp"
#include "behaviours/posture/posture_modules.hpp"
#include "behaviours/stand/stand.hpp"
#include "robot/model/kinematics/nao_fk.hpp"

namespace stride::behaviours {
namespace {

using hal::index;
using hal::JointId;

// Torso pitch and roll seen from a flat foot (pitch > 0 forward, roll > 0 right).
Eigen::Vector2d torso_tilt_over_foot(model::Side side, const std::array<double, 25>& q) {
  model::LegAngles leg{};
  model::gather_chain(model::leg_chain(side), q, leg);
  const Eigen::Matrix3d r = model::torso_in_foot_fk(side, leg).rotation();
  return {std::atan2(-r(2, 0), r(0, 0)), std::atan2(r(2, 1), r(2, 2))};
}

TEST(PostureCorrection, ZeroErrorGivesZeroCorrection) {
  const PostureGains gains = HipStrategyParameters{}.gains();
  const Eigen::Vector4d state(0.05, -0.02, 0.3, -0.1);
  EXPECT_EQ(posture_correction(gains, state, state), Eigen::Vector2d::Zero());
  auto q = stand_posture(StandParameters{});
  const auto reference = q;
  apply_posture_correction(PostureJoints::Hip, Eigen::Vector2d::Zero(), q);
  apply_posture_correction(PostureJoints::Ankle, Eigen::Vector2d::Zero(), q);
  EXPECT_EQ(q, reference);
}

TEST(PostureCorrection, PdLawOfTheThesisWithItsGains) {
  const HipStrategyParameters hip;
  const AnkleStrategyParameters ankle;
  EXPECT_EQ(hip.kp_pitch, 0.40);  // Figs. 4.7-4.8
  EXPECT_EQ(hip.kd_pitch, -0.05);
  EXPECT_EQ(ankle.kp_pitch, 0.28);  // Figs. 4.11-4.12
  EXPECT_EQ(ankle.kd_pitch, -0.06);
  const Eigen::Vector4d desired = Eigen::Vector4d::Zero();
  const Eigen::Vector4d measured(0.1, -0.05, 0.2, 0.4);
  const Eigen::Vector2d d = posture_correction(ankle.gains(), desired, measured);
  EXPECT_NEAR(d[0], 0.28 * -0.1 + -0.06 * -0.2, 1e-15);  // Eq. 4.12
  EXPECT_NEAR(d[1], 0.28 * 0.05 + -0.06 * -0.4, 1e-15);  // Eq. 4.13
}

// Eqs. 4.10-4.11 / 4.14-4.15 in the thesis' (= our NAOqi) signs: with K_p > 0 a lean turns the
// chosen joints so that, over a flat foot, the torso tilts on by exactly K_p times the lean, on
// both legs and with either strategy.
TEST(PostureCorrection, LeansTurnTheJointsAsPrintedOnBothLegs) {
  const auto reference = stand_posture(StandParameters{});
  for (const PostureJoints joints : {PostureJoints::Hip, PostureJoints::Ankle}) {
    const PostureGains gains = joints == PostureJoints::Hip ? HipStrategyParameters{}.gains()
                                                            : AnkleStrategyParameters{}.gains();
    // Forward lean, then a lean to the right, each alone so the angles add exactly.
    for (const Eigen::Vector4d& lean :
         {Eigen::Vector4d(0.1, 0, 0, 0), Eigen::Vector4d(0, 0.06, 0, 0)}) {
      const Eigen::Vector2d d = posture_correction(gains, Eigen::Vector4d::Zero(), lean);
      EXPECT_LE(d[0], 0);  // desired - measured, K_p > 0
      EXPECT_LE(d[1], 0);
      auto q = reference;
      apply_posture_correction(joints, d, q);
      const bool hip = joints == PostureJoints::Hip;
      const JointId moved = lean[0] != 0 ? (hip ? JointId::LHipPitch : JointId::LAnklePitch)
                                         : (hip ? JointId::RHipRoll : JointId::RAnkleRoll);
      EXPECT_NEAR(q[index(moved)] - reference[index(moved)], d[lean[0] != 0 ? 0 : 1], 1e-15);
      for (const model::Side side : {model::Side::Left, model::Side::Right}) {
        const Eigen::Vector2d before = torso_tilt_over_foot(side, reference);
        const Eigen::Vector2d after = torso_tilt_over_foot(side, q);
        EXPECT_NEAR(after[0] - before[0], gains.kp_pitch * lean[0], 1e-9);  // on forwards
        EXPECT_NEAR(after[1] - before[1], gains.kp_roll * lean[1], 1e-9);   // on to the right
      }
    }
  }
}

TEST(PostureCorrection, OnlyTheChosenJointsMove) {
  const auto reference = stand_posture(StandParameters{});
  auto hip = reference, ankle = reference;
  apply_posture_correction(PostureJoints::Hip, {0.02, 0.01}, hip);
  apply_posture_correction(PostureJoints::Ankle, {0.02, 0.01}, ankle);
  for (int j = 0; j < hal::kNumJoints; ++j) {
    const auto id = static_cast<JointId>(j);
    const bool is_hip = id == JointId::LHipPitch || id == JointId::RHipPitch ||
                        id == JointId::LHipRoll || id == JointId::RHipRoll;
    const bool is_ankle = id == JointId::LAnklePitch || id == JointId::RAnklePitch ||
                          id == JointId::LAnkleRoll || id == JointId::RAnkleRoll;
    EXPECT_EQ(hip[j] != reference[j], is_hip) << hal::name(id);
    EXPECT_EQ(ankle[j] != reference[j], is_ankle) << hal::name(id);
  }
}

}  // namespace
}  // namespace stride::behaviours
