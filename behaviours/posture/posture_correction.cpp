#include "behaviours/posture/posture_correction.hpp"

namespace stride::behaviours {

using hal::index;
using hal::JointId;

Eigen::Vector2d posture_correction(const PostureGains& g, const Eigen::Vector4d& desired,
                                   const Eigen::Vector4d& measured) {
  const Eigen::Vector4d e = desired - measured;
  return {g.kp_pitch * e[0] + g.kd_pitch * e[2],  // Eq. 4.8, Eq. 4.12 (ankle)
          g.kp_roll * e[1] + g.kd_roll * e[3]};   // Eq. 4.9, Eq. 4.13 (ankle)
}

void apply_posture_correction(PostureJoints joints, const Eigen::Vector2d& correction,
                              std::array<double, hal::kNumJoints>& position) {
  const bool hip = joints == PostureJoints::Hip;
  const JointId pitch_joints[2] = {hip ? JointId::LHipPitch : JointId::LAnklePitch,
                                   hip ? JointId::RHipPitch : JointId::RAnklePitch};
  const JointId roll_joints[2] = {hip ? JointId::LHipRoll : JointId::LAnkleRoll,
                                  hip ? JointId::RHipRoll : JointId::RAnkleRoll};
  for (const JointId j : pitch_joints)
    position[index(j)] += kJointSignOfCorrection * correction[0];  // Eq. 4.10, Eq. 4.14 (ankle)
  for (const JointId j : roll_joints)
    position[index(j)] += kJointSignOfCorrection * correction[1];  // Eq. 4.11, Eq. 4.15 (ankle)
}

}  // namespace stride::behaviours
