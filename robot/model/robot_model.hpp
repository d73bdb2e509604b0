#pragma once
// Constant description of a robot (the "Model" of a Model/Data split): links, joints, inertias,
// limits and collision primitives, in the URDF's frames. Per-frame state lives elsewhere.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace stride::model {

struct Inertial {
  double mass = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();      // in the link frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the CoM, link-frame axes
};

struct CollisionShape {
  enum class Kind { Box, Sphere, Cylinder };
  Kind kind = Kind::Box;
  Eigen::Vector3d box_size = Eigen::Vector3d::Zero();        // Box: full edge lengths
  double radius = 0;                                         // Sphere, Cylinder
  double length = 0;                                         // Cylinder, along its local z
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // in the link frame
};

enum class JointType { Fixed, Revolute, Continuous, Prismatic };

struct Joint {
  std::string name;
  JointType type = JointType::Fixed;
  int parent_link = -1;
  int child_link = -1;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // child frame in parent frame at q = 0
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();           // unit, in the child frame
  double lower = 0, upper = 0;                               // position limits (rad or m)
  double effort = 0, velocity = 0;                           // limits as the URDF states them
  int mimic_of = -1;  // joint whose value this one copies (one motor, two joints)
  double mimic_multiplier = 1, mimic_offset = 0;

  bool movable() const { return type != JointType::Fixed; }
  bool actuated() const { return movable() && mimic_of < 0; }
};

struct Link {
  std::string name;
  Inertial inertial;
  std::vector<CollisionShape> collisions;
  int parent_joint = -1;  // -1 for the root link
  std::vector<int> child_joints;
};

struct RobotModel {
  std::string name;
  std::string source;  // file it was loaded from
  std::vector<Link> links;
  std::vector<Joint> joints;  // ordered so that every joint's parent link is reached first
  int root_link = 0;

  int link_index(const std::string& link_name) const;    // -1 if absent
  int joint_index(const std::string& joint_name) const;  // -1 if absent
  double total_mass() const;
};

}  // namespace stride::model
