#include "console/session/sim_session.hpp"

#include "behaviours/module_catalogue.hpp"
#include "behaviours/parameter_notes.hpp"
#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "robot/hal/handed_frame_link.hpp"
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

// Robot i's controller in this process, each part built on the one before: the link the
// simulation's frames are handed to, LoLA's packets around it if asked, the runtime, the runtime
// paced by the frames. The simulation calls control_frame(), which also logs the torso's true pose
// beside the blackboard (read only: the run is the same with or without).
struct SimSession::Controller final : hal::FrameController {
  Controller(const ModuleRegistry& registry, const RuntimeConfig& config,
             const sim::SimulatedRobot& robot, bool through_packets,
             std::vector<ControllerChange> changes, Slot& pose_slot)
      : handed(robot.period(), robot.name()),
        packets(through_packets
                    ? std::make_unique<sim::LolaCodecLink>(handed, robot.latest_commands())
                    : nullptr),
        runtime(registry, config, link()),
        paced(runtime, handed, std::move(changes)),
        robot(robot),
        pose(slot_value<SimulatedTorsoPose>(pose_slot)) {
    runtime.log_also(std::string(SimulatedTorsoPose::kTypeName), &pose_slot);
  }

  hal::HardwareLink& link() { return packets ? *packets : handed; }

  bool control_frame(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) override {
    const sim::TorsoPose p = robot.torso_pose();
    pose = {p.x, p.y, p.z, p.roll, p.pitch, p.yaw};
    return paced.control_frame(sensors, commands);
  }

  hal::HandedFrameLink handed;
  std::unique_ptr<hal::HardwareLink> packets;  // null: the runtime reads the handed link
  Runtime runtime;
  PacedRuntime paced;
  const sim::SimulatedRobot& robot;
  SimulatedTorsoPose& pose;
};

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
  controllers_.clear();  // they hold references to the simulated robots
  sim_.reset();
}

Runtime* SimSession::runtime(int robot) {
  return controllers_[robot] ? &controllers_[robot]->runtime : nullptr;
}

PacedRuntime* SimSession::paced_runtime(int robot) {
  return controllers_[robot] ? &controllers_[robot]->paced : nullptr;
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
  poses_.resize(sim_->robot_count());
  std::vector<std::unique_ptr<Controller>> controllers(sim_->robot_count());
  for (int i = 0; i < sim_->robot_count(); ++i) {
    const auto& placement = sim_->scene().robots[i];
    if (!placement.has_controller) continue;
    // The log records where the torso stood; the slot outlives the runtimes that log it.
    if (!poses_[i]) poses_[i] = make_slot<SimulatedTorsoPose>();
    try {
      controllers[i] = std::make_unique<Controller>(registry_, runtime_config(i), sim_->robot(i),
                                                    through_packets_[i],
                                                    placement.controller.changes, *poses_[i]);
    } catch (const Error& e) {
      throw input_error_at(placement.file, placement.line,
                           "<controller>: " + std::string(e.what()));
    }
    check_changes(registry_, runtime_config(i), controllers[i]->link(),
                  placement.controller.changes);
  }
  for (int i = 0; i < sim_->robot_count(); ++i) sim_->set_controller(i, controllers[i].get());
  controllers_ = std::move(controllers);
}

void SimSession::set_frame_observer(int robot, FrameObserver observer) {
  if (robot < 0 || robot >= sim_->robot_count())
    throw Error("no robot " + std::to_string(robot) + " in this scene");
  sim_->set_frame_observer(robot, std::move(observer));
}

void SimSession::route_through_lola_packets(int robot) {
  through_packets_.at(robot) = true;
  attach_controllers();
}

void SimSession::reset() {
  for (int i = 0; i < sim_->robot_count(); ++i) sim_->set_controller(i, nullptr);
  controllers_.clear();
  sim_->reset();
  attach_controllers();
}

}  // namespace stride::console
