#include "behaviours/walking/pattern/pattern_joints.hpp"

#include <Eigen/Geometry>

#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::walking {

namespace {
Eigen::Isometry3d relative_to_waist(const Eigen::Vector3d& foot, const Eigen::Vector3d& waist) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = foot - waist;  // torso frame parallel to the world frame
  return t;
}
}  // namespace

LegJoints leg_joints(const PatternSample& s) {
  const model::LegsIkResult ik = model::legs_ik(relative_to_waist(s.left_foot, s.waist),
                                                relative_to_waist(s.right_foot, s.waist));
  return {ik.left.q, ik.right.q, ik.left.reachable && ik.right.reachable,
          static_cast<std::uint16_t>(ik.left.beyond_limits | (ik.right.beyond_limits << 6))};
}

LegPoints leg_points(model::Side side, const model::LegAngles& q, const Eigen::Vector3d& waist) {
  std::array<Eigen::Isometry3d, 7> frames;
  model::leg_dh_frames(side, q, frames);
  const double y = side == model::Side::Left ? nao::kHipOffsetY : -nao::kHipOffsetY;
  const Eigen::Vector3d hip = waist + Eigen::Vector3d(0, y, -nao::kHipOffsetZ);
  // Knee and ankle from the D-H frames of KneePitch (3) and AnklePitch (4).
  return {hip, waist + frames[3].translation(), waist + frames[4].translation()};
}

}  // namespace stride::walking
