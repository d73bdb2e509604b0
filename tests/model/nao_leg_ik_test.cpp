#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"
#include "robot/nao/nao_dimensions.hpp"
#include "tests/model/nao_model_fixture.hpp"

namespace stride::model {
namespace {

using test::pose_error;

// Leg angles uniform within the NAO's limits (knee from 0: the IK's branch); every tenth sample
// has a knee within 1e-6 rad of stretched.
LegAngles random_leg(Side side, std::mt19937& rng, int i) {
  const double s = side == Side::Left ? 1 : -1;
  auto u = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  LegAngles q;
  q[0] = u(-1.14529, 0.740718);
  q[1] = s > 0 ? u(-0.379435, 0.79046) : u(-0.79046, 0.379435);
  q[2] = u(-1.53589, 0.48398);
  q[3] = i % 10 == 0 ? u(0, 1e-6) : u(0, 2.11255);
  q[4] = u(-1.18944, 0.922581);
  q[5] = s > 0 ? u(-0.397761, 0.768992) : u(-0.768992, 0.397761);
  return q;
}

TEST(LegIk, RoundTripOverTenThousandReachablePoses) {
  std::mt19937 rng(7);
  double worst_pose = 0, worst_angle = 0;
  int unreachable = 0;
  for (int i = 0; i < 10000; ++i) {
    const Side side = i % 2 ? Side::Right : Side::Left;
    const LegAngles q = random_leg(side, rng, i / 2);
    const Eigen::Isometry3d target = leg_fk(side, q);
    const LegIkResult r = leg_ik(side, target);
    unreachable += !r.reachable;
    worst_pose = std::max(worst_pose, pose_error(leg_fk(side, r.q), target));
    if (q[3] > 1e-3)  // away from the stretched knee the angles themselves are unique
      for (int j = 0; j < kLegJoints; ++j)
        worst_angle = std::max(worst_angle, std::abs(r.q[j] - q[j]));
  }
  EXPECT_LT(worst_pose, 1e-9);
  EXPECT_LT(worst_angle, 1e-7);
  EXPECT_LE(unreachable, 10000 / 20);  // only knees within rounding of stretched may flag
}

TEST(LegIk, UnreachablePoseIsClampedFlaggedAndFinite) {
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  target.translation() = Eigen::Vector3d(0.05, 0.05, -0.40);  // 10 cm beyond the stretched leg
  const LegIkResult r = leg_ik(Side::Left, target);
  EXPECT_FALSE(r.reachable);
  EXPECT_TRUE(r.knee_clamped);
  EXPECT_DOUBLE_EQ(r.q[3], 0.0);
  for (double a : r.q) EXPECT_TRUE(std::isfinite(a));
  // The reached ankle lies on the line from the hip to the wanted ankle, at full leg length.
  const Eigen::Vector3d hip(0, nao::kHipOffsetY, -nao::kHipOffsetZ);
  const Eigen::Vector3d ankle = leg_fk(Side::Left, r.q) * Eigen::Vector3d(0, 0, nao::kFootHeight);
  EXPECT_NEAR((ankle - hip).norm(), nao::kThighLength + nao::kTibiaLength, 1e-12);
  const Eigen::Vector3d wanted = target * Eigen::Vector3d(0, 0, nao::kFootHeight) - hip;
  EXPECT_NEAR((ankle - hip).normalized().dot(wanted.normalized()), 1.0, 1e-12);
  EXPECT_NEAR(r.position_error, wanted.norm() - nao::kThighLength - nao::kTibiaLength, 1e-12);
}

TEST(LegIk, SolutionBeyondTheJointLimitsIsReachableButSaysSo) {
  // A knee of 2.6 rad (the limit is 2.11255): the ankle is geometrically reachable.
  const LegAngles bent{0, 0.05, -1.3, 2.6, -1.1, -0.05};
  const LegIkResult r = leg_ik(Side::Left, leg_fk(Side::Left, bent));
  EXPECT_TRUE(r.reachable);
  EXPECT_NEAR(r.q[3], 2.6, 1e-9);
  EXPECT_FALSE(r.within_limits());
  EXPECT_EQ(r.beyond_limits, 1u << 3);  // the knee and nothing else
  // Within the limits: no bit.
  const LegAngles stand{0, 0, -0.4, 0.8, -0.4, 0};
  EXPECT_TRUE(leg_ik(Side::Left, leg_fk(Side::Left, stand)).within_limits());
  // The right leg's roll limits are mirrored: a hip roll of +0.5 is beyond it (max 0.379435).
  const LegAngles rolled{0, 0.5, -0.4, 0.8, -0.4, -0.3};
  EXPECT_EQ(leg_ik(Side::Right, leg_fk(Side::Right, rolled)).beyond_limits, 1u << 1);
  EXPECT_EQ(leg_limit_violations(Side::Left, rolled), 0u);
  // Both legs: the right leg keeps its own bits.
  const LegsIkResult both = legs_ik(leg_fk(Side::Left, stand), leg_fk(Side::Right, rolled));
  EXPECT_TRUE(both.left.within_limits());
  EXPECT_EQ(both.right.beyond_limits, 1u << 1);
}

TEST(LegIk, NoJumpWhenCrossingTheStretchedBoundary) {
  LegAngles q{0, 0.1, -0.4, 0.3, -0.2, -0.05};
  Eigen::Isometry3d target = leg_fk(Side::Left, q);
  LegAngles previous = leg_ik(Side::Left, target).q;
  double worst_step = 0;
  for (int i = 0; i < 6000; ++i) {  // 6 cm downwards in 10 um steps, through the boundary
    target.translation().z() -= 1e-5;
    const LegIkResult r = leg_ik(Side::Left, target);
    for (int j = 0; j < kLegJoints; ++j) {
      ASSERT_TRUE(std::isfinite(r.q[j]));
      worst_step = std::max(worst_step, std::abs(r.q[j] - previous[j]));
    }
    previous = r.q;
  }
  EXPECT_FALSE(leg_ik(Side::Left, target).reachable);
  EXPECT_LT(worst_step, 0.03);  // the knee moves like sqrt(distance) near stretched
}

TEST(LegIk, SharedHipYawPitchReachesBothConsistentTargets) {
  std::mt19937 rng(3);
  for (int i = 0; i < 500; ++i) {
    LegAngles l = random_leg(Side::Left, rng, 1), r = random_leg(Side::Right, rng, 1);
    r[0] = l[0];
    const Eigen::Isometry3d lt = leg_fk(Side::Left, l), rt = leg_fk(Side::Right, r);
    const LegsIkResult both = legs_ik(lt, rt);
    EXPECT_DOUBLE_EQ(both.left.q[0], both.right.q[0]);
    EXPECT_LT(pose_error(leg_fk(Side::Left, both.left.q), lt), 1e-9);
    EXPECT_LT(pose_error(leg_fk(Side::Right, both.right.q), rt), 1e-9);
    EXPECT_LT(both.right.orientation_error, 1e-9);
  }
}

TEST(LegIk, ConflictingTargetsLeftWinsRightAnklePositionStillReached) {
  const LegAngles l{-0.4, 0.1, -0.5, 0.8, -0.3, -0.1};
  const LegAngles r{0.0, -0.1, -0.5, 0.8, -0.3, 0.1};  // wants yaw-pitch 0
  const Eigen::Isometry3d rt = leg_fk(Side::Right, r);
  const LegsIkResult both = legs_ik(leg_fk(Side::Left, l), rt);
  EXPECT_NEAR(both.right.q[0], -0.4, 1e-12);
  EXPECT_GT(both.right.orientation_error, 0.01);
  const Eigen::Vector3d up(0, 0, nao::kFootHeight);
  const Eigen::Vector3d reached_ankle = leg_fk(Side::Right, both.right.q) * up;
  EXPECT_LT((reached_ankle - rt * up).norm(), 1e-9);
}

// Foot yaw relative to the torso (turning walks): opposite yaws of mirrored feet are reached
// exactly by both legs through the one HipYawPitch, whose angle grows with the yaw (toes out:
// negative).
TEST(LegIk, MirroredFeetWithOppositeYawsAreBothReachedExactly) {
  const Eigen::Vector3d left(0.02, 0.06, -0.30), right(0.02, -0.06, -0.30);
  double previous_hyp = 1.0;
  for (double yaw = -0.3; yaw <= 0.3001; yaw += 0.05) {
    const LegsIkResult r = legs_ik_upright(left, yaw, right, -yaw);
    EXPECT_TRUE(r.left.reachable && r.right.reachable) << yaw;
    EXPECT_EQ(r.left.beyond_limits | r.right.beyond_limits, 0) << yaw;
    EXPECT_LT(r.right.orientation_error, 1e-9) << yaw;
    const Eigen::Isometry3d lf = leg_fk(Side::Left, r.left.q), rf = leg_fk(Side::Right, r.right.q);
    EXPECT_LT((lf.translation() - left).norm(), 1e-9) << yaw;
    EXPECT_LT((rf.translation() - right).norm(), 1e-9) << yaw;
    EXPECT_NEAR(std::atan2(lf.linear()(1, 0), lf.linear()(0, 0)), yaw, 1e-9);
    EXPECT_NEAR(std::atan2(rf.linear()(1, 0), rf.linear()(0, 0)), -yaw, 1e-9);
    EXPECT_NEAR(lf.linear()(2, 2), 1.0, 1e-9) << "the sole stays flat";
    EXPECT_LT(r.left.q[0], previous_hyp) << "HipYawPitch falls as the toes turn out";
    previous_hyp = r.left.q[0];
  }
  EXPECT_NEAR(legs_ik_upright(left, 0.0, right, 0.0).left.q[0], 0.0, 1e-12);
}

// Feet apart in x and z (a step) with opposite yaws about the torso are not both reachable: the
// HipYawPitch a yawed foot needs depends on where it is. legs_ik_turned finds the torso yaw that
// makes them so.
TEST(LegIk, TurnedFeetOfAStepAreReachedExactlyAtTheTorsoYawFound) {
  const Eigen::Vector3d left(0.03, 0.05, -0.30), right(-0.025, -0.045, -0.28);
  const LegsIkResult plain = legs_ik_upright(left, 0.2, right, -0.2);
  EXPECT_GT(plain.right.orientation_error, 0.005);
  for (double turn : {-0.4, -0.1, 0.0, 0.15, 0.3}) {
    for (double heading : {0.0, 1.0, 3.1}) {  // the same step facing elsewhere, across +-pi
      const Eigen::Matrix3d h = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).matrix();
      const TurnedLegsIkResult r =
          legs_ik_turned(h * left, heading + turn, h * right, heading - turn);
      EXPECT_LT(r.yaw_error, 1e-10) << turn << " " << heading;
      EXPECT_LT(r.legs.right.orientation_error, 1e-9) << turn << " " << heading;
      EXPECT_NEAR(std::remainder(r.torso_yaw - heading, 2 * M_PI), 0.0, 0.05);
      const Eigen::Matrix3d torso =
          Eigen::AngleAxisd(r.torso_yaw, Eigen::Vector3d::UnitZ()).matrix();
      const Eigen::Isometry3d lf = leg_fk(Side::Left, r.legs.left.q);
      const Eigen::Isometry3d rf = leg_fk(Side::Right, r.legs.right.q);
      EXPECT_LT((torso * lf.translation() - h * left).norm(), 1e-9);
      EXPECT_LT((torso * rf.translation() - h * right).norm(), 1e-9);
      const Eigen::Matrix3d lw = torso * lf.linear(), rw = torso * rf.linear();
      EXPECT_NEAR(std::remainder(std::atan2(lw(1, 0), lw(0, 0)) - heading - turn, 2 * M_PI), 0,
                  1e-9);
      EXPECT_NEAR(std::remainder(std::atan2(rw(1, 0), rw(0, 0)) - heading + turn, 2 * M_PI), 0,
                  1e-9);
      EXPECT_NEAR(rw(2, 2), 1.0, 1e-9) << "the right sole stays flat";
      EXPECT_DOUBLE_EQ(r.legs.left.q[0], r.legs.right.q[0]);
    }
  }
}

TEST(LegIk, TorsoYawBetweenIsTheMeanAlongTheShorterArc) {
  EXPECT_NEAR(torso_yaw_between(0.2, -0.1), 0.05, 1e-15);
  EXPECT_NEAR(torso_yaw_between(3.0, -3.0), M_PI, 1e-12);  // across +-pi, not through 0
  EXPECT_NEAR(std::abs(torso_yaw_between(-3.1, 3.1)), M_PI, 1e-12);
  EXPECT_NEAR(torso_yaw_between(1.0, 1.0), 1.0, 1e-15);
}

}  // namespace
}  // namespace stride::model
