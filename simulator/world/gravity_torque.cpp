#include "simulator/world/gravity_torque.hpp"

#include "robot/core/error.hpp"

namespace stride::sim {

double gravity_torque_about_joint(const RobotBody& body, const std::string& joint,
                                  std::initializer_list<const char*> links, double gravity) {
  const auto& m = body.model();
  const int j = m.joint_index(joint);
  if (j < 0) throw Error("no joint '" + joint + "' in " + m.source);
  const Eigen::Isometry3d frame = body.link_pose(m.joints[j].child_link);
  const Eigen::Vector3d axis = frame.linear() * m.joints[j].axis;
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  for (const char* name : links) {
    const int l = m.link_index(name);
    if (l < 0) throw Error(std::string("no link '") + name + "' in " + m.source);
    const Eigen::Vector3d arm = body.link_com(l) - frame.translation();
    torque += arm.cross(Eigen::Vector3d(0, 0, -gravity * m.links[l].inertial.mass));
  }
  return torque.dot(axis);
}

}  // namespace stride::sim
