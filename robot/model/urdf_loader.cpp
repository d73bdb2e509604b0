#include "robot/model/urdf_loader.hpp"

#include <map>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"
#include "robot/core/input_file.hpp"
#include "robot/model/urdf_validation.hpp"

namespace stride::model {
namespace {

Eigen::Isometry3d to_isometry(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  t.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  return t;
}

Inertial to_inertial(const urdf::InertialSharedPtr& in) {
  Inertial out;
  if (!in) return out;
  out.mass = in->mass;
  const Eigen::Isometry3d o = to_isometry(in->origin);
  out.com = o.translation();
  Eigen::Matrix3d i;
  i << in->ixx, in->ixy, in->ixz, in->ixy, in->iyy, in->iyz, in->ixz, in->iyz, in->izz;
  out.inertia = o.linear() * i * o.linear().transpose();  // URDF inertia axes may be rotated
  return out;
}

CollisionShape to_shape(const urdf::Collision& c) {
  CollisionShape s;
  s.origin = to_isometry(c.origin);
  switch (c.geometry->type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(*c.geometry);
      s.kind = CollisionShape::Kind::Box;
      s.box_size = Eigen::Vector3d(b.dim.x, b.dim.y, b.dim.z);
      break;
    }
    case urdf::Geometry::SPHERE:
      s.kind = CollisionShape::Kind::Sphere;
      s.radius = static_cast<const urdf::Sphere&>(*c.geometry).radius;
      break;
    case urdf::Geometry::CYLINDER: {
      const auto& cy = static_cast<const urdf::Cylinder&>(*c.geometry);
      s.kind = CollisionShape::Kind::Cylinder;
      s.radius = cy.radius;
      s.length = cy.length;
      break;
    }
    default:
      throw Error("mesh geometry is not supported");  // validation reports it with a line first
  }
  return s;
}

JointType to_type(int t) {
  switch (t) {
    case urdf::Joint::REVOLUTE:
      return JointType::Revolute;
    case urdf::Joint::CONTINUOUS:
      return JointType::Continuous;
    case urdf::Joint::PRISMATIC:
      return JointType::Prismatic;
    default:
      return JointType::Fixed;
  }
}

Joint to_joint(const urdf::Joint& j, int parent_link) {
  Joint joint;
  joint.name = j.name;
  joint.type = to_type(j.type);
  joint.parent_link = parent_link;
  joint.origin = to_isometry(j.parent_to_joint_origin_transform);
  joint.axis = Eigen::Vector3d(j.axis.x, j.axis.y, j.axis.z).normalized();  // validated non-zero
  if (j.limits) {
    joint.lower = j.limits->lower;
    joint.upper = j.limits->upper;
    joint.effort = j.limits->effort;
    joint.velocity = j.limits->velocity;
  }
  return joint;
}

int add_link(const urdf::Link& l, int parent_joint, RobotModel& model) {
  Link link;
  link.name = l.name;
  link.inertial = to_inertial(l.inertial);
  for (const auto& c : l.collision_array) link.collisions.push_back(to_shape(*c));
  if (l.collision_array.empty() && l.collision) link.collisions.push_back(to_shape(*l.collision));
  link.parent_joint = parent_joint;
  const int id = static_cast<int>(model.links.size());
  model.links.push_back(std::move(link));
  if (parent_joint >= 0) model.joints[parent_joint].child_link = id;
  return id;
}

// Depth first from the root, so every joint follows its parent link; an explicit stack (child
// joints pushed in reverse) gives the order a recursive walk would, without its depth.
void add_tree(const urdf::ModelInterface& urdf, RobotModel& model) {
  std::vector<std::pair<urdf::JointConstSharedPtr, int>> stack;  // joint, its parent link
  const auto push_children = [&](const urdf::Link& l, int id) {
    for (auto it = l.child_joints.rbegin(); it != l.child_joints.rend(); ++it)
      stack.emplace_back(*it, id);
  };
  const urdf::LinkConstSharedPtr root = urdf.getRoot();
  push_children(*root, add_link(*root, -1, model));
  model.root_link = 0;
  while (!stack.empty()) {
    const auto [j, parent] = stack.back();
    stack.pop_back();
    const int jid = static_cast<int>(model.joints.size());
    model.joints.push_back(to_joint(*j, parent));
    model.links[parent].child_joints.push_back(jid);
    const urdf::LinkConstSharedPtr child = urdf.getLink(j->child_link_name);
    push_children(*child, add_link(*child, jid, model));
  }
}

}  // namespace

RobotModel parse_urdf(const std::string& xml, const std::string& source_name) {
  validate_urdf_text(xml, source_name);
  // urdfdom logs its own multi-line messages; our error below is the one line the user sees.
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
  urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDF(xml);
  if (!urdf || !urdf->getRoot())
    throw error_at(source_name, 1,
                   "urdfdom rejected the robot (check link/joint names and the tree)");

  RobotModel model;
  model.name = urdf->getName();
  model.source = source_name;
  add_tree(*urdf, model);
  for (auto& joint : model.joints) {  // resolve mimic names once every joint exists
    urdf::JointConstSharedPtr j = urdf->getJoint(joint.name);
    if (j && j->mimic) {  // validated: a movable joint that mimics none
      joint.mimic_of = model.joint_index(j->mimic->joint_name);
      joint.mimic_multiplier = j->mimic->multiplier;
      joint.mimic_offset = j->mimic->offset;
    }
  }
  return model;
}

RobotModel load_urdf(const std::string& given) {
  const std::string path = find_input(given);  // a shipped robot from any working directory
  const std::string text = read_input_file(path, kMaxTextInputBytes, "URDF file");
  try {
    return parse_urdf(text, path);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(e.what());
  }
}

}  // namespace stride::model
