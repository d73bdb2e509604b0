#include "console/view/walk_plan_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "console/view/kinematic_frame.hpp"

namespace stride::view {

namespace {

double yaw_of(const Eigen::Isometry3d& p) {
  return std::atan2(p.linear()(1, 0), p.linear()(0, 0));
}

int link_index(const model::RobotModel& m, const std::string& name) {
  for (std::size_t i = 0; i < m.links.size(); ++i)
    if (m.links[i].name == name) return static_cast<int>(i);
  return -1;
}

// x, y, yaw of the planned support (both feet: their midpoint) and of the drawn one.
std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> anchors(const RobotFrame& f,
                                                                   const model::RobotModel& m,
                                                                   const WalkPlanValues& p) {
  const int l = link_index(m, "LFoot"), r = link_index(m, "RFoot");
  const int n = static_cast<int>(f.links.size());
  if (l < 0 || r < 0 || l >= n || r >= n) return std::nullopt;
  auto drawn = [&](int i) {
    const Eigen::Isometry3d& pose = f.links[i];
    return Eigen::Vector3d(pose.translation().x(), pose.translation().y(), yaw_of(pose));
  };
  const Eigen::Vector3d pl(p.left[0], p.left[1], p.left[2]), pr(p.right[0], p.right[1], p.right[2]);
  if (p.support == 1) return std::pair{pl, drawn(l)};
  if (p.support == 2) return std::pair{pr, drawn(r)};
  const Eigen::Vector3d dl = drawn(l), dr = drawn(r);
  Eigen::Vector3d mid = (dl + dr) / 2;
  mid.z() = std::atan2(std::sin(dl.z()) + std::sin(dr.z()), std::cos(dl.z()) + std::cos(dr.z()));
  return std::pair{Eigen::Vector3d((pl + pr) / 2), mid};
}

}  // namespace

// "{t=1, zmp=[0.1, 0.2], ...}" (how `get` prints a struct of numbers and number arrays) ->
// each field's numbers; a field whose value is not numbers is left out.
std::map<std::string, std::vector<double>, std::less<>> struct_numbers(std::string_view text) {
  std::map<std::string, std::vector<double>, std::less<>> out;
  if (!text.starts_with('{') || !text.ends_with('}')) return out;
  text = text.substr(1, text.size() - 2);
  int depth = 0;
  std::size_t from = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && (text[i] == '[' || text[i] == '{')) ++depth;
    if (i < text.size() && (text[i] == ']' || text[i] == '}')) --depth;
    if (i < text.size() && !(text[i] == ',' && depth == 0)) continue;
    std::string_view item = text.substr(from, i - from);
    from = i + 1;
    while (item.starts_with(' ')) item.remove_prefix(1);
    const std::size_t eq = item.find('=');
    if (eq == std::string_view::npos) continue;
    const std::string_view v = item.substr(eq + 1);
    std::vector<double> n =
        numbers(v.starts_with('[') ? std::string(v) : "[" + std::string(v) + "]");
    if (!n.empty()) out.emplace(std::string(item.substr(0, eq)), std::move(n));
  }
  return out;
}

std::optional<WalkPlanValues> read_walk_plan(std::string_view printed) {
  const auto f = struct_numbers(printed);
  auto field = [&](const char* name, std::size_t size) -> const std::vector<double>* {
    const auto it = f.find(name);
    return it != f.end() && (size == 0 || it->second.size() == size) ? &it->second : nullptr;
  };
  const auto *zmp = field("zmp", 2), *support = field("support", 1), *left = field("left_foot", 3),
             *right = field("right_foot", 3), *steps = field("steps", 1);
  const auto *xs = field("step_x", 0), *ys = field("step_y", 0), *yaws = field("step_yaw", 0),
             *feet = field("step_foot", 0);
  if (!zmp || !support || !left || !right || !steps || !xs || !ys || !yaws || !feet)
    return std::nullopt;
  // Both feet at one place: a WalkPlan never written (e.g. a log from before it was recorded).
  if (*left == *right) return std::nullopt;
  WalkPlanValues p;
  p.zmp = {(*zmp)[0], (*zmp)[1]};
  p.support = static_cast<int>((*support)[0]);
  p.left = {(*left)[0], (*left)[1], (*left)[2]};
  p.right = {(*right)[0], (*right)[1], (*right)[2]};
  const std::size_t n = static_cast<std::size_t>(std::clamp((*steps)[0], 0.0, 64.0));
  for (std::size_t i = 0;
       i < n && i < xs->size() && i < ys->size() && i < yaws->size() && i < feet->size(); ++i)
    p.steps.push_back({(*xs)[i], (*ys)[i], (*yaws)[i], (*feet)[i]});
  return p;
}

void stand_on_plan(RobotFrame& f, const model::RobotModel& model, const WalkPlanValues& p) {
  const auto a = anchors(f, model, p);
  if (!a) return;
  const auto& [plan, drawn] = *a;
  Eigen::Isometry3d move = Eigen::Isometry3d::Identity();
  move.translate(Eigen::Vector3d(plan.x(), plan.y(), 0));
  move.rotate(Eigen::AngleAxisd(plan.z() - drawn.z(), Eigen::Vector3d::UnitZ()));
  move.translate(Eigen::Vector3d(-drawn.x(), -drawn.y(), 0));
  for (auto& link : f.links) link = move * link;
  if (f.com) f.com = move * *f.com;
  auto flat = [&](const Eigen::Vector2d& v) {
    return Eigen::Vector2d((move * Eigen::Vector3d(v.x(), v.y(), 0)).head<2>());
  };
  for (auto& v : f.support) v = flat(v);
  if (f.cop) f.cop = flat(*f.cop);
  for (auto& [point, force] : f.contacts) {
    point = move * point;
    force = move.linear() * force;
  }
}

void place_walk_plan(RobotFrame& f, const model::RobotModel& model, const WalkPlanValues& p) {
  const auto a = anchors(f, model, p);
  if (!a) return;
  const auto& [plan, drawn] = *a;
  const double yaw = drawn.z() - plan.z(), c = std::cos(yaw), s = std::sin(yaw);
  auto place = [&](double x, double y) {
    const double dx = x - plan.x(), dy = y - plan.y();
    return Eigen::Vector2d(drawn.x() + c * dx - s * dy, drawn.y() + s * dx + c * dy);
  };
  // The walk frame's origin and heading in the world, so anyone can map the plan's values.
  const Eigen::Vector2d origin = place(0, 0);
  f.walk_frame = Eigen::Vector3d(origin.x(), origin.y(), yaw);
  f.zmp_ref = place(p.zmp[0], p.zmp[1]);
  for (const auto& st : p.steps) {
    const Eigen::Vector2d at = place(st[0], st[1]);
    f.footsteps.push_back({Eigen::Vector3d(at.x(), at.y(), st[2] + yaw), st[3] == 1});
  }
}

}  // namespace stride::view
