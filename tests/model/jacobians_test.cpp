#include <gtest/gtest.h>

#include <random>

#include "robot/model/kinematics/dls_ik.hpp"
#include "robot/model/kinematics/jacobians.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "tests/model/nao_model_fixture.hpp"

namespace stride::model {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// Twist that carries pose a to pose b in unit time, [v; omega] in a's reference frame.
Vector6d twist_between(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::AngleAxisd r(b.linear() * a.linear().transpose());
  Vector6d t;
  t << b.translation() - a.translation(), r.angle() * r.axis();
  return t;
}

LegAngles random_leg(std::mt19937& rng) {
  LegAngles q;
  for (double& x : q) x = std::uniform_real_distribution<double>(-0.6, 0.6)(rng);
  q[3] = std::abs(q[3]) + 0.2;
  return q;
}

template <typename Fk>
Matrix6d numeric_jacobian(const Fk& fk, const LegAngles& q, bool in_end_frame) {
  constexpr double h = 1e-7;
  Matrix6d j;
  for (int i = 0; i < kLegJoints; ++i) {
    LegAngles lo = q, hi = q;
    lo[i] -= h;
    hi[i] += h;
    const Eigen::Isometry3d a = fk(lo), b = fk(hi);
    Vector6d t = twist_between(a, b) / (2 * h);
    if (in_end_frame) {
      const Eigen::Matrix3d r = fk(q).linear().transpose();
      t.head<3>() = r * t.head<3>();
      t.tail<3>() = r * t.tail<3>();
    }
    j.col(i) = t;
  }
  return j;
}

TEST(LegJacobians, MatchFiniteDifferencesOfTheForwardKinematics) {  // App. D
  std::mt19937 rng(5);
  for (int trial = 0; trial < 100; ++trial) {
    for (Side side : {Side::Left, Side::Right}) {
      const LegAngles q = random_leg(rng);
      const auto sole = [&](const LegAngles& x) { return leg_fk(side, x); };
      const auto torso = [&](const LegAngles& x) { return torso_in_foot_fk(side, x); };
      EXPECT_LT((leg_jacobian(side, q) - numeric_jacobian(sole, q, false)).cwiseAbs().maxCoeff(),
                1e-7);
      EXPECT_LT(
          (leg_jacobian_in_foot(side, q) - numeric_jacobian(sole, q, true)).cwiseAbs().maxCoeff(),
          1e-7);
      EXPECT_LT((torso_jacobian_in_foot(side, q) - numeric_jacobian(torso, q, false))
                    .cwiseAbs()
                    .maxCoeff(),
                1e-7);
    }
  }
}

TEST(ComJacobian, MatchesFiniteDifferencesIncludingTheMimicHip) {
  const RobotModel& m = test::nao_model();
  const NaoJointMap map = make_nao_joint_map(m);
  std::mt19937 rng(6);
  std::vector<Eigen::Isometry3d> poses;
  Eigen::Matrix3Xd j(3, m.joints.size());
  JointVector q;
  for (int trial = 0; trial < 20; ++trial) {
    joints_from_lola(m, map, test::random_lola(rng), q);
    link_poses(m, q, poses);
    com_jacobian(m, poses, j);
    for (size_t k = 0; k < m.joints.size(); ++k) {
      if (!m.joints[k].actuated()) {
        EXPECT_EQ(j.col(k).norm(), 0.0);
        continue;
      }
      constexpr double h = 1e-6;
      JointVector lo = q, hi = q;
      lo[k] -= h;
      hi[k] += h;
      apply_mimic(m, lo);
      apply_mimic(m, hi);
      link_poses(m, hi, poses);
      const Eigen::Vector3d c_hi = centre_of_mass(m, poses);
      link_poses(m, lo, poses);
      const Eigen::Vector3d c_lo = centre_of_mass(m, poses);
      EXPECT_LT((j.col(k) - (c_hi - c_lo) / (2 * h)).cwiseAbs().maxCoeff(), 1e-8)
          << m.joints[k].name;
    }
  }
}

TEST(DlsIk, ReachesRandomArmPosesFromNearbyStarts) {
  const RobotModel& m = test::nao_model();
  const NaoJointMap map = make_nao_joint_map(m);
  const int hand = m.link_index("LHand");
  std::mt19937 rng(8);
  std::vector<Eigen::Isometry3d> poses;
  DlsIkWorkspace work;
  JointVector goal, q;
  int converged = 0;
  for (int trial = 0; trial < 100; ++trial) {
    joints_from_lola(m, map, test::random_lola(rng), goal);
    link_poses(m, goal, poses);
    const Eigen::Isometry3d target = poses[hand];
    q = goal;
    for (int k = 0; k < q.size(); ++k)
      q[k] += std::uniform_real_distribution<double>(-0.2, 0.2)(rng);
    const DlsIkResult r = dls_ik(m, hand, target, q, work);
    link_poses(m, q, poses);
    if (r.converged) {
      ++converged;
      EXPECT_LT(test::pose_error(poses[hand], target), 1e-9);
    }
  }
  EXPECT_GE(converged, 95);  // a start may sit across a joint limit from the goal
}

TEST(DlsIk, UnreachableTargetStopsFiniteAndUnconverged) {
  const RobotModel& m = test::nao_model();
  DlsIkWorkspace work;
  JointVector q = zero_joints(m);
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(1.0, 1.0, 1.0);
  const DlsIkResult r = dls_ik(m, m.link_index("LHand"), far, q, work);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(q.allFinite());
}

}  // namespace
}  // namespace stride::model
