#include "robot/model/urdf_loader.hpp"

#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"
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
  std::map<std::string, int> link_ids;
  // Depth-first from the root so every joint follows its parent link.
  std::function<void(const urdf::LinkConstSharedPtr&, int)> visit =
      [&](const urdf::LinkConstSharedPtr& l, int parent_joint) {
        Link link;
        link.name = l->name;
        link.inertial = to_inertial(l->inertial);
        for (const auto& c : l->collision_array) link.collisions.push_back(to_shape(*c));
        if (l->collision_array.empty() && l->collision)
          link.collisions.push_back(to_shape(*l->collision));
        link.parent_joint = parent_joint;
        const int id = static_cast<int>(model.links.size());
        link_ids[l->name] = id;
        model.links.push_back(std::move(link));
        if (parent_joint >= 0) model.joints[parent_joint].child_link = id;
        for (const auto& j : l->child_joints) {
          Joint joint;
          joint.name = j->name;
          joint.type = to_type(j->type);
          joint.parent_link = id;
          joint.origin = to_isometry(j->parent_to_joint_origin_transform);
          Eigen::Vector3d axis(j->axis.x, j->axis.y, j->axis.z);
          joint.axis =
              axis.norm() > 0 ? Eigen::Vector3d(axis.normalized()) : Eigen::Vector3d::UnitX();
          if (j->limits) {
            joint.lower = j->limits->lower;
            joint.upper = j->limits->upper;
            joint.effort = j->limits->effort;
            joint.velocity = j->limits->velocity;
          }
          const int jid = static_cast<int>(model.joints.size());
          model.joints.push_back(joint);
          model.links[id].child_joints.push_back(jid);
          visit(urdf->getLink(j->child_link_name), jid);
        }
      };
  visit(urdf->getRoot(), -1);
  model.root_link = 0;

  for (auto& joint : model.joints) {  // resolve mimic names once every joint exists
    urdf::JointConstSharedPtr j = urdf->getJoint(joint.name);
    if (j && j->mimic) {
      joint.mimic_of = model.joint_index(j->mimic->joint_name);
      if (joint.mimic_of < 0)
        throw error_at(
            source_name, 1,
            "joint '" + joint.name + "' mimics unknown joint '" + j->mimic->joint_name + "'");
      joint.mimic_multiplier = j->mimic->multiplier;
      joint.mimic_offset = j->mimic->offset;
    }
  }
  return model;
}

RobotModel load_urdf(const std::string& given) {
  const std::string path = find_input(given);  // a shipped robot from any working directory
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open URDF file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_urdf(ss.str(), path);
}

}  // namespace stride::model
