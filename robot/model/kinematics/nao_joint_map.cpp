#include "robot/model/kinematics/nao_joint_map.hpp"

#include <string>

namespace stride::model {

NaoJointMap make_nao_joint_map(const RobotModel& model) {
  NaoJointMap map;
  for (int i = 0; i < hal::kNumJoints; ++i)
    map.model_index[i] = model.joint_index(std::string(hal::kJointNames[i]));
  map.rhip_yaw_pitch = model.joint_index("RHipYawPitch");
  return map;
}

void joints_from_lola(const RobotModel& model, const NaoJointMap& map,
                      std::span<const double, hal::kNumJoints> lola, JointVector& q) {
  if (q.size() != static_cast<Eigen::Index>(model.joints.size())) q = zero_joints(model);
  for (int i = 0; i < hal::kNumJoints; ++i)
    if (map.model_index[i] >= 0) q[map.model_index[i]] = lola[i];
  apply_mimic(model, q);
}

void joints_to_lola(const NaoJointMap& map, const JointVector& q,
                    std::span<double, hal::kNumJoints> lola) {
  for (int i = 0; i < hal::kNumJoints; ++i)
    lola[i] = map.model_index[i] >= 0 ? q[map.model_index[i]] : 0.0;
}

}  // namespace stride::model
