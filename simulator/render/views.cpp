#include "simulator/render/views.hpp"

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "simulator/simulation.hpp"

namespace stride::render {
namespace {

struct BuiltinView {
  const char* name;
  Eigen::Vector3d offset;  // eye relative to the framed point, world frame
};
// Distances frame a standing NAO (0.57 m tall) with some floor around it.
const BuiltinView kBuiltins[] = {
    {"follow", {0.8, -0.65, 0.35}},
    {"front", {1.0, 0.0, 0.05}},
    {"side", {0.0, -1.0, 0.05}},
    {"top", {0.0, 0.0, 1.3}},
};

Eigen::Vector3d framed_point(const sim::Simulation& sim, int robot) {
  if (robot < 0 || robot >= sim.robot_count()) return Eigen::Vector3d(0, 0, 0.2);
  const auto torso = sim.robot(robot).torso_pose();
  return Eigen::Vector3d(torso.x, torso.y, 0.25);  // mid-height of the robot, not the torso
}

}  // namespace

std::vector<std::string> view_names(const sim::Simulation& sim) {
  std::vector<std::string> out;
  for (const BuiltinView& b : kBuiltins) out.emplace_back(b.name);
  for (const sim::SceneCamera& c : sim.scene().cameras) out.push_back(c.name);
  return out;
}

CameraView resolve_view(const sim::Simulation& sim, const std::string& name, int robot) {
  const std::string want = name.empty() ? "follow" : name;
  for (const sim::SceneCamera& c : sim.scene().cameras)
    if (c.name == want) {
      CameraView v;
      v.eye = c.eye;
      v.target = c.look_at;
      v.fov = c.fov;
      v.width = c.width;
      v.height = c.height;
      return v;
    }
  for (const BuiltinView& b : kBuiltins)
    if (want == b.name) {
      CameraView v;
      v.target = framed_point(sim, robot);
      v.eye = v.target + b.offset;
      return v;
    }
  std::string known;
  for (const std::string& n : view_names(sim)) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown view " + quote(want) + " (expected one of: " + known + ")");
}

}  // namespace stride::render
