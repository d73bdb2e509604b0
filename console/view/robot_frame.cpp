#include "console/view/robot_frame.hpp"

#include <algorithm>

#include "simulator/simulation.hpp"

namespace stride::view {

namespace {

Json optional_json(const std::optional<Eigen::Vector2d>& p) {
  return p ? point2_json(*p) : Json(nullptr);
}

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

}  // namespace

std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {  // upper chain
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0) --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

Json robot_frame_json(const RobotFrame& f) {
  Json links = Json::array(), support = Json::array(), contacts = Json::array(),
       steps = Json::array();
  for (const auto& l : f.links) links.push_back(pose_json(l));
  for (const auto& s : f.support) support.push_back(point2_json(s));
  for (const auto& [p, force] : f.contacts) {
    Json c = point_json(p);
    for (const auto& v : point_json(force)) c.push_back(v);
    contacts.push_back(std::move(c));
  }
  for (const auto& s : f.footsteps) {
    Json step = point_json(s.pose);
    step.push_back(s.left ? "left" : "right");
    steps.push_back(std::move(step));
  }
  return {{"name", f.name},
          {"links", std::move(links)},
          {"com", f.com ? point_json(*f.com) : Json(nullptr)},
          {"zmp_ref", optional_json(f.zmp_ref)},
          {"cop", optional_json(f.cop)},
          {"support", std::move(support)},
          {"contacts", std::move(contacts)},
          {"footsteps", std::move(steps)},
          {"walk_frame", f.walk_frame ? point_json(*f.walk_frame) : Json(nullptr)},
          {"fell", f.fell}};
}

RobotFrame simulated_robot_frame(const sim::Simulation& simulation, int i) {
  const sim::SimulatedRobot& robot = simulation.robot(i);
  const sim::RobotBody& body = robot.body();
  RobotFrame f;
  f.name = robot.name();
  for (int l = 0; l < body.link_count(); ++l) f.links.push_back(body.link_pose(l));
  f.com = body.centre_of_mass();
  f.fell = robot.fallen();
  std::vector<Eigen::Vector2d> points;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  double vertical = 0;
  for (const sim::ContactRecord& c : simulation.world().contacts()) {
    const bool on_a = c.a && c.a->robot == i, on_b = c.b && c.b->robot == i;
    if (on_a == on_b) continue;  // another robot's, or the robot touching itself
    const Eigen::Vector3d force = on_a ? c.force_on_a : c.force_on_b;
    f.contacts.emplace_back(c.position, force);
    points.push_back(c.position.head<2>());
    if (force.z() > 0) {
      moment += force.z() * c.position.head<2>();
      vertical += force.z();
    }
  }
  f.support = convex_hull(std::move(points));
  if (vertical > 1e-6) f.cop = moment / vertical;  // pressure centre of the vertical forces
  return f;
}

}  // namespace stride::view
