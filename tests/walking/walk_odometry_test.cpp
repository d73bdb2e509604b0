// Walk odometry and the heading hold (behaviours/walking/odometry, steps/heading_hold): the leg
// odometry chains the support foot and gives back a torso path that was walked on known
// footholds, exactly; the heading hold turns the straight pattern's frame about the support foot
// by its gain's share of the measured heading, clamped a step, keeps the support foot where and
// how it stands, lands the swing foot on the turned heading, and changes nothing at gain 0.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "behaviours/walking/odometry/leg_odometry.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "behaviours/walking/steps/heading_hold.hpp"
#include "robot/model/kinematics/nao_fk.hpp"

namespace stride::walking {
namespace {

Eigen::Vector2d in_torso(const Eigen::Vector2d& foot, const Eigen::Vector2d& torso, double yaw) {
  return rotated(-yaw, foot.x() - torso.x(), foot.y() - torso.y());
}

// A torso walking an arc on footholds placed along it: the odometry gives its path back.
TEST(LegOdometry, ChainsTheSupportFootAlongAWalkedArc) {
  const double radius = 2.0, d0 = 0.05;
  const auto torso_at = [&](double a) {
    return Eigen::Vector2d(radius * std::sin(a), radius * (1 - std::cos(a)));
  };
  const auto foothold = [&](double a, double side) {
    return torso_at(a) + rotated(a, 0.0, side * d0);
  };
  LegOdometryState s;
  Eigen::Vector2d left = foothold(0, 1), right = foothold(0, -1);
  constexpr int kSteps = 20, kFrames = 30;
  for (int k = 0; k < kSteps; ++k) {
    const bool left_supports = k % 2 == 0;
    for (int f = 0; f < kFrames; ++f) {
      const double a = (k + static_cast<double>(f) / kFrames) * 0.05;
      const Eigen::Vector2d torso = torso_at(a);
      // The swing foot moves on its way to the next foothold but carries no load.
      if (left_supports)
        right = foothold(a + 0.05, -1);
      else
        left = foothold(a + 0.05, 1);
      s = advance_leg_odometry(s, a, in_torso(left, torso, a), in_torso(right, torso, a),
                               left_supports ? 200.0 : 0.0, left_supports ? 0.0 : 200.0, 0.7);
      ASSERT_NEAR(s.torso.x(), torso.x(), 1e-12) << k << " " << f;
      ASSERT_NEAR(s.torso.y(), torso.y(), 1e-12) << k << " " << f;
    }
  }
  EXPECT_EQ(s.exchanges, kSteps - 1);
  EXPECT_EQ(s.support, OdometrySupport::right);
  EXPECT_NEAR(s.yaw, (kSteps - 1.0 / kFrames) * 0.05, 1e-12);
}

// While the load is shared below the exchange share, the support stays with the foot it was on.
TEST(LegOdometry, KeepsTheSupportUntilTheOtherFootTakesTheShare) {
  LegOdometryState s;
  const Eigen::Vector2d l(0.0, 0.05), r(0.0, -0.05);
  s = advance_leg_odometry(s, 0.0, l, r, 0.0, 0.0, 0.7);
  EXPECT_EQ(s.support, OdometrySupport::none);
  s = advance_leg_odometry(s, 0.0, l, r, 80.0, 20.0, 0.7);
  EXPECT_EQ(s.support, OdometrySupport::left);
  EXPECT_NEAR(s.foot.y(), 0.05, 1e-15);
  s = advance_leg_odometry(s, 0.0, l, r, 40.0, 60.0, 0.7);
  EXPECT_EQ(s.support, OdometrySupport::left);
  s = advance_leg_odometry(s, 0.0, l, r, 20.0, 80.0, 0.7);
  EXPECT_EQ(s.support, OdometrySupport::right);
  EXPECT_EQ(s.exchanges, 1);
}

// The sole's yaw in the torso frame and its place there, from the joints.
struct SoleSeen {
  Eigen::Vector3d at;
  double yaw;
};
SoleSeen sole(model::Side side, const LegJoints& q) {
  const Eigen::Isometry3d f = model::leg_fk(side, side == model::Side::Left ? q.left : q.right);
  return {f.translation(), std::atan2(f.linear()(1, 0), f.linear()(0, 0))};
}

// Gain 0 plays the pattern as the thesis' walk: the same joints as its straight IK.
TEST(HeadingHold, AtGainZeroTheJointsAreThePatterns) {
  const PatternParameters p = preset("medium");
  const StretchedKneePattern pattern(p);
  HeadingHold hold;
  for (double t = 0.0; t <= 4.0; t += 0.01) {
    const PatternSample s = pattern.sample(t);
    const HeldJoints held = hold.joints(s, t, 0.3, {0.0, 0.1, 2.0 * p.T_s()});
    const LegJoints straight = leg_joints(s);
    for (int j = 0; j < model::kLegJoints; ++j) {
      ASSERT_NEAR(held.legs.left[j], straight.left[j], 1e-9) << t;
      ASSERT_NEAR(held.legs.right[j], straight.right[j], 1e-9) << t;
    }
  }
}

// The feet spun sigma to the left on the floor: the measured yaw is the torso's commanded yaw
// plus sigma. At gain 1 the hold turns the frame back until it faces -sigma, at most 0.1 rad a
// step (sigma 0.5: five full turns first), and a foot that has just landed stands turned from the
// other by the last swing's turn (the HipYawPitch's work), within the joint limits throughout.
TEST(HeadingHold, TurnsTheFrameBackByTheSpinClampedAStep) {
  for (const double sigma : {0.05, 0.5}) {
    const PatternParameters p = preset("medium");
    const StretchedKneePattern pattern(p);
    HeadingHold hold;
    SupportPhase last = SupportPhase::kDouble;
    double torso_yaw = 0.0, landed_yaw = 0.0;
    std::vector<double> turns;
    for (double t = 0.0; t <= 12.0; t += 0.01) {
      const PatternSample s = pattern.sample(t);
      const HeldJoints j = hold.joints(s, t, torso_yaw + sigma, {1.0, 0.1, 2.0 * p.T_s()});
      torso_yaw = j.torso_yaw;
      ASSERT_EQ(j.legs.beyond_limits, 0) << t;
      ASSERT_TRUE(j.legs.reachable) << t;
      if (last != SupportPhase::kDouble && s.support != last) {  // a swing ended
        turns.push_back(hold.frame().yaw - landed_yaw);
        landed_yaw = hold.frame().yaw;
        const double rel =
            sole(model::Side::Left, j.legs).yaw - sole(model::Side::Right, j.legs).yaw;
        const double left_landed = last == SupportPhase::kRight ? 1.0 : -1.0;
        EXPECT_NEAR(rel * left_landed, turns.back(), 1e-6) << t;
        EXPECT_LE(std::abs(turns.back()), 0.1 + 1e-12) << t;
      }
      last = s.support;
    }
    ASSERT_GT(turns.size(), 20u);
    if (sigma > 0.1)
      for (int i = 0; i < 5; ++i) EXPECT_NEAR(turns[i], -0.1, 1e-12) << i;
    EXPECT_NEAR(hold.frame().yaw, -sigma, 1e-3);
  }
}

}  // namespace
}  // namespace stride::walking
