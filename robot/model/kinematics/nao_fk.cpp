#include "robot/model/kinematics/nao_fk.hpp"

#include <numbers>

#include "robot/core/error.hpp"
#include "robot/model/kinematics/dh.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::model {
namespace {

using std::numbers::pi;
using namespace stride::nao;

// Table B.1 (head).
constexpr std::array<DhRow, 2> kHeadDh = {{{0, 0, 0, 0}, {-pi / 2, 0, 0, -pi / 2}}};

// Table B.4 (left leg, RCS) and B.5 (right leg, RCS).
constexpr std::array<DhRow, 6> kLeftLegDh = {{{-3 * pi / 4, 0, 0, -pi / 2},
                                              {-pi / 2, 0, 0, pi / 4},
                                              {pi / 2, 0, 0, 0},
                                              {0, -kThighLength, 0, 0},
                                              {0, -kTibiaLength, 0, 0},
                                              {-pi / 2, 0, 0, 0}}};
constexpr std::array<DhRow, 6> kRightLegDh = {{{-pi / 4, 0, 0, -pi / 2},
                                               {-pi / 2, 0, 0, -pi / 4},
                                               {pi / 2, 0, 0, 0},
                                               {0, -kThighLength, 0, 0},
                                               {0, -kTibiaLength, 0, 0},
                                               {-pi / 2, 0, 0, 0}}};
// Table B.8 flips the left leg's roll angles; with the rows of Table B.4 as printed and the
// robot's own sign convention (positive LHipRoll moves the leg outwards) no flip is needed, which
// the comparison with the URDF confirms. The FCS walk uses the opposite sign of every joint.
constexpr std::array<double, 6> kLeftLegSign = {1, 1, 1, 1, 1, 1};
constexpr std::array<double, 6> kRightLegSign = {1, 1, 1, 1, 1, 1};

// Table B.2 (arms). The thesis shifts the base by ElbowOffsetY, which is exact only at zero
// ShoulderRoll; the offset belongs to the upper arm, so it goes into a_2 of row 3 instead.
std::array<DhRow, 5> arm_dh(Side side) {
  const double s = side == Side::Left ? 1 : -1;
  return {{{-pi / 2, 0, 0, 0},
           {pi / 2, 0, 0, pi / 2},
           {pi / 2, s * kElbowOffsetY, kUpperArmLength, 0},
           {-pi / 2, 0, 0, 0},
           {pi / 2, 0, kLowerArmLength, 0}}};
}

// Tables B.6 and B.7 (FCS): rows in foot-to-hip order, angles AnkleRoll .. HipYawPitch.
// Row 5 needs the same -/+ pi/4 hip-roll offset as Table B.4/B.5 (missing in B.6/B.7), else
// the yaw-pitch axis would not sit at 45 degrees to the hip pitch axis.
constexpr std::array<DhRow, 6> kLeftLegFootDh = {{{0, 0, 0, 0},
                                                  {pi / 2, 0, 0, 0},
                                                  {0, kTibiaLength, 0, 0},
                                                  {0, kThighLength, 0, 0},
                                                  {-pi / 2, 0, 0, -pi / 4},
                                                  {pi / 2, 0, 0, -pi / 4}}};
constexpr std::array<DhRow, 6> kRightLegFootDh = {{{0, 0, 0, 0},
                                                   {pi / 2, 0, 0, 0},
                                                   {0, kTibiaLength, 0, 0},
                                                   {0, kThighLength, 0, 0},
                                                   {-pi / 2, 0, 0, pi / 4},
                                                   {pi / 2, 0, 0, pi / 4}}};

const Eigen::Isometry3d& leg_end() {  // 6T_End of Tables B.4/B.5
  static const Eigen::Isometry3d t = rot_z(pi) * rot_y(-pi / 2) * trans(0, 0, -kFootHeight);
  return t;
}

Eigen::Isometry3d leg_base(Side side) {
  return trans(0, side == Side::Left ? kHipOffsetY : -kHipOffsetY, -kHipOffsetZ);
}

Eigen::Isometry3d head_fk(std::span<const double> q) {
  static const Eigen::Isometry3d end = rot_x(pi / 2) * rot_y(pi / 2);
  return trans(0, 0, kNeckOffsetZ) * dh_transform(kHeadDh[0], q[0]) *
         dh_transform(kHeadDh[1], q[1]) * end;
}

}  // namespace

double leg_dh_sign(Side side, int joint) {
  return side == Side::Left ? kLeftLegSign[joint] : kRightLegSign[joint];
}

void leg_dh_frames(Side side, const LegAngles& q, std::array<Eigen::Isometry3d, 7>& frames) {
  const auto& table = side == Side::Left ? kLeftLegDh : kRightLegDh;
  Eigen::Isometry3d t = leg_base(side);
  for (int i = 0; i < kLegJoints; ++i) {
    t = t * dh_transform(table[i], leg_dh_sign(side, i) * q[i]);
    frames[i] = t;
  }
  frames[6] = t * leg_end();
}

Eigen::Isometry3d leg_fk(Side side, const LegAngles& q) {
  std::array<Eigen::Isometry3d, 7> frames;
  leg_dh_frames(side, q, frames);
  return frames[6];
}

namespace {

Eigen::Isometry3d foot_dh_walk(Side side, const LegAngles& q) {
  static const Eigen::Isometry3d base = trans(0, 0, kFootHeight) * rot_z(pi) * rot_y(-pi / 2);
  const auto& table = side == Side::Left ? kLeftLegFootDh : kRightLegFootDh;
  Eigen::Isometry3d t = base;
  for (int i = 0; i < kLegJoints; ++i) {
    const int joint = kLegJoints - 1 - i;                                  // ankle roll first
    t = t * dh_transform(table[i], -leg_dh_sign(side, joint) * q[joint]);  // Table B.8, FCS
  }
  return t;
}

// 6T_End of Tables B.6/B.7: Rot * Trans(0, -/+HipOffsetY, HipOffsetZ). The printed rotations do
// not close the chain onto the torso axes; the rotation is the one that does at q = 0.
Eigen::Isometry3d foot_end(Side side) {
  const LegAngles zero{};
  const Eigen::Matrix3d r =
      foot_dh_walk(side, zero).linear().transpose() * leg_fk(side, zero).linear().transpose();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = r;
  return t * trans(0, side == Side::Left ? -kHipOffsetY : kHipOffsetY, kHipOffsetZ);
}

}  // namespace

Eigen::Isometry3d torso_in_foot_fk(Side side, const LegAngles& q) {
  static const Eigen::Isometry3d left_end = foot_end(Side::Left);
  static const Eigen::Isometry3d right_end = foot_end(Side::Right);
  return foot_dh_walk(side, q) * (side == Side::Left ? left_end : right_end);
}

Eigen::Isometry3d arm_fk(Side side, std::span<const double> q) {
  static const std::array<DhRow, 5> left = arm_dh(Side::Left), right = arm_dh(Side::Right);
  static const Eigen::Isometry3d end = rot_y(-pi / 2) * rot_x(-pi / 2) * trans(kHandOffsetX, 0, 0);
  const auto& table = side == Side::Left ? left : right;
  Eigen::Isometry3d t =
      trans(0, side == Side::Left ? kShoulderOffsetY : -kShoulderOffsetY, kShoulderOffsetZ);
  for (int i = 0; i < 5; ++i) t = t * dh_transform(table[i], q[i]);
  return t * end;
}

Eigen::Isometry3d chain_fk(NaoChain chain, std::span<const double> q) {
  if (q.size() != chain_joints(chain).size())
    throw Error("chain_fk: " + std::string(chain_name(chain)) + " expects " +
                std::to_string(chain_joints(chain).size()) + " angles, got " +
                std::to_string(q.size()));
  switch (chain) {
    case NaoChain::Head:
      return head_fk(q);
    case NaoChain::LLeg:
    case NaoChain::RLeg: {
      LegAngles a;
      std::copy(q.begin(), q.end(), a.begin());
      return leg_fk(chain == NaoChain::LLeg ? Side::Left : Side::Right, a);
    }
    case NaoChain::LArm:
      return arm_fk(Side::Left, q);
    case NaoChain::RArm:
      return arm_fk(Side::Right, q);
  }
  return Eigen::Isometry3d::Identity();
}

}  // namespace stride::model
