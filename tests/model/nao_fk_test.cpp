#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "robot/model/kinematics/dh.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/nao/nao_dimensions.hpp"
#include "tests/model/nao_model_fixture.hpp"

namespace stride::model {
namespace {

using test::nao_model;
using test::pose_error;

TEST(DhTransform, MatchesTheProductOfElementaryTransforms) {  // Eq. B.1
  const DhRow row{0.3, 0.02, -0.05, 0.1};
  const Eigen::Isometry3d expected =
      rot_x(0.3) * trans(0.02, 0, 0) * rot_z(0.7 + 0.1) * trans(0, 0, -0.05);
  EXPECT_LT(pose_error(dh_transform(row, 0.7), expected), 1e-15);
}

TEST(NaoFk, StandingZeroPoseSoleIsBelowTheHip) {
  const LegAngles zero{};
  const Eigen::Vector3d p = leg_fk(Side::Left, zero).translation();
  EXPECT_NEAR(p.x(), 0, 1e-15);
  EXPECT_NEAR(p.y(), nao::kHipOffsetY, 1e-15);
  EXPECT_NEAR(p.z(), -(nao::kHipOffsetZ + nao::kThighLength + nao::kTibiaLength + nao::kFootHeight),
              1e-15);
}

// All five chains (and the FCS legs) against the generic URDF tree walk, 1,000 random postures.
TEST(NaoFk, AgreesWithGenericLinkPosesOverRandomPostures) {
  const RobotModel& m = nao_model();
  const NaoJointMap map = make_nao_joint_map(m);
  std::mt19937 rng(42);
  std::vector<Eigen::Isometry3d> poses;
  JointVector q;
  const auto link = [&](const char* name) { return poses[m.link_index(name)]; };
  const Eigen::Isometry3d to_hand = trans(nao::kHandOffsetX, 0, 0);
  const Eigen::Isometry3d to_sole = trans(0, 0, -nao::kFootHeight);
  double worst = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const auto lola = test::random_lola(rng);
    joints_from_lola(m, map, lola, q);
    link_poses(m, q, poses);
    const auto chain = [&](NaoChain c) {
      std::array<double, 6> a{};
      const size_t n = chain_joints(c).size();
      gather_chain(c, lola, std::span<double>(a.data(), n));
      return chain_fk(c, std::span<const double>(a.data(), n));
    };
    LegAngles l, r;
    gather_chain(NaoChain::LLeg, lola, std::span<double>(l));
    gather_chain(NaoChain::RLeg, lola, std::span<double>(r));
    const double errors[] = {
        pose_error(chain(NaoChain::Head), link("Head")),
        pose_error(chain(NaoChain::LArm), link("LHand") * to_hand),
        pose_error(chain(NaoChain::RArm), link("RHand") * to_hand),
        pose_error(chain(NaoChain::LLeg), link("LFoot") * to_sole),
        pose_error(chain(NaoChain::RLeg), link("RFoot") * to_sole),
        pose_error(torso_in_foot_fk(Side::Left, l), (link("LFoot") * to_sole).inverse()),
        pose_error(torso_in_foot_fk(Side::Right, r), (link("RFoot") * to_sole).inverse())};
    for (double e : errors) worst = std::max(worst, e);
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(NaoFk, WrongAngleCountIsAnError) {
  const double q[3] = {0, 0, 0};
  EXPECT_THROW(chain_fk(NaoChain::Head, q), Error);
}

}  // namespace
}  // namespace stride::model
