#include "robot/model/robot_model.hpp"

namespace stride::model {

int RobotModel::link_index(const std::string& link_name) const {
  for (size_t i = 0; i < links.size(); ++i)
    if (links[i].name == link_name) return static_cast<int>(i);
  return -1;
}

int RobotModel::joint_index(const std::string& joint_name) const {
  for (size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == joint_name) return static_cast<int>(i);
  return -1;
}

double RobotModel::total_mass() const {
  double m = 0;
  for (const auto& l : links) m += l.inertial.mass;
  return m;
}

}  // namespace stride::model
