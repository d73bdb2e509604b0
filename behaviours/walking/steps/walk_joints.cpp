#include "behaviours/walking/steps/walk_joints.hpp"

#include "robot/model/kinematics/nao_leg_ik.hpp"

namespace stride::walking {

WalkJoints leg_joints(const WalkSample& s) {
  const model::TurnedLegsIkResult ik = model::legs_ik_turned(
      s.left.position - s.waist, s.left.yaw, s.right.position - s.waist, s.right.yaw);
  const model::LegsIkResult& l = ik.legs;
  return {{l.left.q, l.right.q, l.left.reachable && l.right.reachable,
           static_cast<std::uint16_t>(l.left.beyond_limits | (l.right.beyond_limits << 6))},
          ik.torso_yaw,
          ik.yaw_error};
}

}  // namespace stride::walking
