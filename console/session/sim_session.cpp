#include "console/session/sim_session.hpp"

#include "behaviours/module_catalogue.hpp"
#include "robot/core/error.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::console {

namespace {
sim::SceneDescription load(const std::string& path, std::optional<std::uint64_t> seed) {
  sim::SceneDescription s = sim::parse_scene_file(path);
  if (seed) s.physics.seed = *seed;
  return s;
}
}  // namespace

SimSession::SimSession(const std::string& scene_path, std::optional<std::uint64_t> seed)
    : SimSession(load(scene_path, seed)) {}

SimSession::SimSession(sim::SceneDescription scene) {
  behaviours::register_all_modules(registry_);
  sim_ = std::make_unique<sim::Simulation>(std::move(scene));
  attach_controllers();
}

SimSession::~SimSession() {
  runtimes_.clear();  // runtimes hold references to the simulated robots
  sim_.reset();
}

RuntimeConfig SimSession::runtime_config(int robot) const {
  const auto& c = sim_->scene().robots[robot].controller;
  return RuntimeConfig{c.providers, c.parameters};
}

void SimSession::attach_controllers() {
  std::vector<std::unique_ptr<Runtime>> runtimes(sim_->robot_count());
  for (int i = 0; i < sim_->robot_count(); ++i) {
    const auto& placement = sim_->scene().robots[i];
    if (!placement.has_controller) continue;
    try {
      runtimes[i] = std::make_unique<Runtime>(registry_, runtime_config(i), sim_->robot(i));
    } catch (const Error& e) {
      throw error_at(placement.file, placement.line, "<controller>: " + std::string(e.what()));
    }
  }
  runtimes_ = std::move(runtimes);
  for (int i = 0; i < sim_->robot_count(); ++i) {
    Runtime* rt = runtimes_[i].get();
    if (rt) sim_->set_controller(i, [rt](sim::SimulatedRobot&) { rt->step(); });
  }
}

void SimSession::reset() {
  runtimes_.clear();
  sim_->reset();
  attach_controllers();
}

}  // namespace stride::console
