#include "console/session/sim_session.hpp"

#include "behaviours/module_catalogue.hpp"
#include "robot/core/error.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::console {

namespace {
void apply_change(Runtime& rt, const sim::ControllerChange& c) {
  if (c.kind == sim::ControllerChange::Kind::Provider) {
    rt.swap_provider(c.first, c.second);
    return;
  }
  const auto dot = c.first.find('.');
  rt.set_parameters(c.first.substr(0, dot), c.first.substr(dot + 1) + "=" + c.second);
}

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
    // Timed changes are tried in order on a scratch controller so a bad one fails at load.
    if (!placement.controller.changes.empty()) {
      Runtime scratch(registry_, runtime_config(i), sim_->robot(i));
      for (const auto& c : placement.controller.changes) {
        try {
          apply_change(scratch, c);
        } catch (const Error& e) {
          throw error_at(c.file, c.line, "<at>: " + std::string(e.what()));
        }
      }
    }
  }
  runtimes_ = std::move(runtimes);
  for (int i = 0; i < sim_->robot_count(); ++i) {
    Runtime* rt = runtimes_[i].get();
    if (!rt) continue;
    const auto* changes = &sim_->scene().robots[i].controller.changes;
    sim::Simulation* sim = sim_.get();
    sim_->set_controller(
        i, [rt, changes, sim, next = std::size_t{0}](sim::SimulatedRobot&) mutable {
          while (next < changes->size() && (*changes)[next].time <= sim->time() + 1e-9)
            apply_change(*rt, (*changes)[next++]);
          rt->step();
        });
  }
}

void SimSession::reset() {
  runtimes_.clear();
  sim_->reset();
  attach_controllers();
}

}  // namespace stride::console
