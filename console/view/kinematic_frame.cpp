#include "console/view/kinematic_frame.hpp"

#include <limits>

#include "robot/core/number_text.hpp"
#include "robot/model/link_poses.hpp"

namespace stride::view {

namespace {

// The items of "[a, b, c]" (or of "a, b"), trimmed.
std::vector<std::string_view> items(std::string_view text) {
  if (text.starts_with('[')) text.remove_prefix(1);
  if (text.ends_with(']')) text.remove_suffix(1);
  std::vector<std::string_view> out;
  while (!text.empty()) {
    const std::size_t comma = std::min(text.find(','), text.size());
    std::string_view item = text.substr(0, comma);
    while (item.starts_with(' ')) item.remove_prefix(1);
    while (item.ends_with(' ')) item.remove_suffix(1);
    out.push_back(item);
    text.remove_prefix(std::min(comma + 1, text.size()));
  }
  return out;
}

bool number_of(std::string_view word, double& out) {
  if (!is_number(word)) return false;
  out = parse_number(word, "value");
  return true;
}

// World corners of a link's boxes (feet are boxes in the shipped URDFs), or the link origin.
std::vector<Eigen::Vector3d> contact_points(const model::Link& link,
                                            const Eigen::Isometry3d& pose) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& c : link.collisions) {
    if (c.kind != model::CollisionShape::Kind::Box) continue;
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector3d corner(((i & 1) ? 0.5 : -0.5) * c.box_size.x(),
                                   ((i & 2) ? 0.5 : -0.5) * c.box_size.y(),
                                   ((i & 4) ? 0.5 : -0.5) * c.box_size.z());
      out.push_back(pose * (c.origin * corner));
    }
  }
  if (out.empty()) out.push_back(pose.translation());
  return out;
}

}  // namespace

std::map<std::string, double> named_numbers(std::string_view text) {
  std::map<std::string, double> out;
  for (std::string_view item : items(text)) {
    const std::size_t eq = item.find('=');
    double v = 0;
    if (eq != std::string_view::npos && number_of(item.substr(eq + 1), v))
      out[std::string(item.substr(0, eq))] = v;
  }
  return out;
}

std::vector<double> numbers(std::string_view text) {
  std::vector<double> out;
  for (std::string_view item : items(text)) {
    double v = 0;
    if (!number_of(item, v)) return {};
    out.push_back(v);
  }
  return out;
}

std::vector<std::string> strings(std::string_view text) {
  std::vector<std::string> out;
  for (std::string_view item : items(text)) {
    if (item.size() >= 2 && item.front() == '"' && item.back() == '"')
      item = item.substr(1, item.size() - 2);
    out.emplace_back(item);
  }
  return out;
}

namespace {
// Every link's pose in the torso's frame for the named joint angles (others at zero).
std::vector<Eigen::Isometry3d> torso_frame_poses(const model::RobotModel& model,
                                                 const std::map<std::string, double>& joints) {
  model::JointVector q = model::zero_joints(model);
  for (std::size_t j = 0; j < model.joints.size(); ++j)
    if (const auto it = joints.find(model.joints[j].name); it != joints.end()) q[j] = it->second;
  model::apply_mimic(model, q);
  std::vector<Eigen::Isometry3d> poses;
  model::link_poses(model, q, poses);
  return poses;
}

// The frame of a robot whose torso is at `torso`; what lies within 5 mm of the floor supports it.
RobotFrame frame_at(const model::RobotModel& model, const std::string& name,
                    const std::vector<Eigen::Isometry3d>& poses, const Eigen::Isometry3d& torso) {
  RobotFrame f;
  f.name = name;
  std::vector<Eigen::Vector2d> ground;
  for (std::size_t l = 0; l < model.links.size(); ++l) {
    f.links.push_back(torso * poses[l]);
    for (const auto& p : contact_points(model.links[l], f.links.back()))
      if (p.z() < 0.005) ground.push_back(p.head<2>());
  }
  f.support = convex_hull(std::move(ground));
  f.com = torso * model::centre_of_mass(model, poses);
  return f;
}
}  // namespace

RobotFrame posed_robot_frame(const model::RobotModel& model, const std::string& name,
                             const std::map<std::string, double>& joints,
                             const Eigen::Isometry3d& torso) {
  return frame_at(model, name, torso_frame_poses(model, joints), torso);
}

RobotFrame kinematic_robot_frame(const model::RobotModel& model, const std::string& name,
                                 const std::map<std::string, double>& joints, double roll,
                                 double pitch) {
  const std::vector<Eigen::Isometry3d> poses = torso_frame_poses(model, joints);
  Eigen::Isometry3d torso = Eigen::Isometry3d::Identity();
  torso.linear() = (Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                    Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                       .toRotationMatrix();
  // The lowest point of the tilted robot stands on the ground.
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t l = 0; l < model.links.size(); ++l)
    for (const auto& p : contact_points(model.links[l], torso * poses[l]))
      lowest = std::min(lowest, p.z());
  torso.translation().z() = -lowest;
  return frame_at(model, name, poses, torso);
}

}  // namespace stride::view
