#include "robot/model/link_poses.hpp"

namespace stride::model {

JointVector zero_joints(const RobotModel& model) {
  return JointVector::Zero(static_cast<Eigen::Index>(model.joints.size()));
}

void apply_mimic(const RobotModel& model, JointVector& q) {
  for (size_t j = 0; j < model.joints.size(); ++j) {
    const Joint& jt = model.joints[j];
    if (jt.mimic_of >= 0) q[j] = jt.mimic_multiplier * q[jt.mimic_of] + jt.mimic_offset;
  }
}

Eigen::Isometry3d joint_transform(const Joint& joint, double qi) {
  Eigen::Isometry3d t = joint.origin;
  switch (joint.type) {
    case JointType::Revolute:
    case JointType::Continuous:
      t.rotate(Eigen::AngleAxisd(qi, joint.axis));
      break;
    case JointType::Prismatic:
      t.translate(qi * joint.axis);
      break;
    case JointType::Fixed:
      break;
  }
  return t;
}

void link_poses(const RobotModel& model, const JointVector& q,
                std::vector<Eigen::Isometry3d>& out) {
  out.resize(model.links.size());
  out[model.root_link] = Eigen::Isometry3d::Identity();
  for (size_t j = 0; j < model.joints.size(); ++j) {  // joints are in parent-first order
    const Joint& jt = model.joints[j];
    out[jt.child_link] = out[jt.parent_link] * joint_transform(jt, q[j]);
  }
}

Eigen::Vector3d centre_of_mass(const RobotModel& model,
                               const std::vector<Eigen::Isometry3d>& poses) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double m = 0;
  for (size_t i = 0; i < model.links.size(); ++i) {
    const Inertial& in = model.links[i].inertial;
    sum += in.mass * (poses[i] * in.com);
    m += in.mass;
  }
  return m > 0 ? Eigen::Vector3d(sum / m) : Eigen::Vector3d::Zero();  // Eq. 3.17
}

}  // namespace stride::model
