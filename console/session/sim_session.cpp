#include "console/session/sim_session.hpp"

#include "behaviours/module_catalogue.hpp"
#include "behaviours/parameter_notes.hpp"
#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "robot/runtime/controller_schedule.hpp"
#include "robot/runtime/world_pose.hpp"
#include "simulator/lola/lola_codec_link.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::console {

void add_parameter_overrides(sim::SceneDescription& scene,
                             const std::vector<ParameterOverride>& overrides,
                             const std::string& what) {
  if (overrides.empty()) return;
  if (scene.robots.empty() || !scene.robots[0].has_controller)
    throw Error(what + ": robot 0 of " + quote(scene.name) + " has no <controller>");
  for (const ParameterOverride& o : overrides)
    scene.robots[0].controller.parameters[o.key.module + "." + o.key.field] = o.value;
}

namespace {
sim::SceneDescription load(const std::string& path, std::optional<std::uint64_t> seed,
                           const std::vector<ParameterOverride>& overrides) {
  sim::SceneDescription s = sim::parse_scene_file(path);
  if (seed) s.physics.seed = *seed;
  add_parameter_overrides(s, overrides, "--set");
  return s;
}
}  // namespace

std::vector<std::string> parameter_notes(const Runtime& runtime) {
  std::vector<std::string> notes;
  for (const std::string& module : runtime.module_order())
    if (const Slot* p = runtime.parameters_of(module))
      for (std::string& n : behaviours::parameter_notes(module, *p)) notes.push_back(std::move(n));
  return notes;
}

SimSession::SimSession(const std::string& scene_path, std::optional<std::uint64_t> seed,
                       const std::vector<ParameterOverride>& overrides)
    : SimSession(load(scene_path, seed, overrides)) {}

SimSession::SimSession(sim::SceneDescription scene) {
  behaviours::register_all_modules(registry_);
  try {
    sim_ = std::make_unique<sim::Simulation>(std::move(scene));
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {  // what the scene builds (URDF, devices, limits) is the input's fault
    throw InputError(e.what());
  }
  attach_controllers();
}

SimSession::~SimSession() {
  runtimes_.clear();  // runtimes hold references to the simulated robots
  sim_.reset();
}

RuntimeConfig SimSession::runtime_config(int robot) const {
  const auto& c = sim_->scene().robots[robot].controller;
  return RuntimeConfig{c.providers, c.parameters, models_[robot]};
}

void SimSession::attach_controllers() {
  // The controllers' robot models are the simulated robots' own, loaded once from their URDFs.
  models_.clear();
  for (int i = 0; i < sim_->robot_count(); ++i)
    models_.push_back(std::make_shared<const model::RobotModel>(sim_->robot(i).model()));
  through_packets_.resize(sim_->robot_count());
  std::vector<std::unique_ptr<hal::HardwareLink>> links(sim_->robot_count());
  std::vector<std::unique_ptr<Runtime>> runtimes(sim_->robot_count());
  for (int i = 0; i < sim_->robot_count(); ++i) {
    const auto& placement = sim_->scene().robots[i];
    if (!placement.has_controller) continue;
    if (through_packets_[i]) links[i] = std::make_unique<sim::LolaCodecLink>(sim_->robot(i));
    hal::HardwareLink& link = links[i] ? *links[i] : sim_->robot(i);
    try {
      runtimes[i] = std::make_unique<Runtime>(registry_, runtime_config(i), link);
    } catch (const Error& e) {
      throw input_error_at(placement.file, placement.line,
                           "<controller>: " + std::string(e.what()));
    }
    check_changes(registry_, runtime_config(i), link, placement.controller.changes);
  }
  runtimes_.clear();  // before the links they use
  packet_links_ = std::move(links);
  runtimes_ = std::move(runtimes);
  observers_.resize(sim_->robot_count());
  poses_.resize(sim_->robot_count());
  for (int i = 0; i < sim_->robot_count(); ++i) {
    Runtime* rt = runtimes_[i].get();
    const FrameObserver* observer = &observers_[i];
    if (!rt) {
      sim_->set_controller(i, [observer](sim::SimulatedRobot& robot) {
        if (*observer) (*observer)(robot);
      });
      continue;
    }
    sim::Simulation* sim = sim_.get();
    // The log records where the torso stood (read only: the run is the same with or without).
    if (!poses_[i]) poses_[i] = make_slot<SimulatedTorsoPose>();
    rt->log_also(std::string(SimulatedTorsoPose::kTypeName), poses_[i].get());
    auto& pose = slot_value<SimulatedTorsoPose>(*poses_[i]);
    sim_->set_controller(
        i, [rt, sim, observer, &pose,
            schedule = ControllerSchedule(sim_->scene().robots[i].controller.changes)](
               sim::SimulatedRobot& robot) mutable {
          schedule.apply_due(*rt, sim->time());
          const sim::TorsoPose p = robot.torso_pose();
          pose = {p.x, p.y, p.z, p.roll, p.pitch, p.yaw};
          rt->step();
          if (*observer) (*observer)(robot);
        });
  }
}

void SimSession::set_frame_observer(int robot, FrameObserver observer) {
  if (robot < 0 || robot >= static_cast<int>(observers_.size()))
    throw Error("no robot " + std::to_string(robot) + " in this scene");
  observers_[robot] = std::move(observer);
}

void SimSession::route_through_lola_packets(int robot) {
  through_packets_.at(robot) = true;
  attach_controllers();
}

void SimSession::reset() {
  runtimes_.clear();
  sim_->reset();
  attach_controllers();
}

}  // namespace stride::console
