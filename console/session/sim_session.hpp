#pragma once
// A loaded scene with its controllers: the Simulation plus one Runtime per robot that has a
// <controller>, each handed its robot's frames (PacedRuntime, a hal::FrameController), so the
// Simulation's step() runs them. Console commands and `stride run` act on this.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robot/framework/module_registry.hpp"
#include "robot/runtime/paced_runtime.hpp"
#include "robot/runtime/parameter_override.hpp"
#include "robot/runtime/runtime.hpp"
#include "simulator/simulation.hpp"

namespace stride::console {

// Puts `overrides` into robot 0's controller configuration, after the scene's own parameters
// (they win); throws stride::Error naming `what` when robot 0 has no <controller>.
void add_parameter_overrides(sim::SceneDescription& scene,
                             const std::vector<ParameterOverride>& overrides,
                             const std::string& what);

// Notes on the parameters of `runtime`'s running modules that no NAO could use, one line each
// ("PatternWalk: T_stride = 0.01 s: ..."; behaviours/parameter_notes.hpp).
std::vector<std::string> parameter_notes(const Runtime& runtime);

class SimSession {
 public:
  // Loads the scene and builds its controllers; throws stride::Error and builds nothing on error.
  // `overrides` go to robot 0's controller (add_parameter_overrides).
  explicit SimSession(const std::string& scene_path,
                      std::optional<std::uint64_t> seed = std::nullopt,
                      const std::vector<ParameterOverride>& overrides = {});
  explicit SimSession(sim::SceneDescription scene);
  ~SimSession();

  sim::Simulation& simulation() { return *sim_; }
  const sim::Simulation& simulation() const { return *sim_; }
  // The controller of robot `i`, or nullptr if the scene gives it none.
  Runtime* runtime(int robot);
  // Robot `i`'s runtime as the simulation drives it, or nullptr (for a test that times its step).
  PacedRuntime* paced_runtime(int robot);
  const ModuleRegistry& registry() const { return registry_; }
  RuntimeConfig runtime_config(int robot) const;

  // Rebuilds world and controllers from the same description (observers are kept).
  void reset();

  // From now on (also after reset()) robot `i`'s controller talks to it through LoLA's packets
  // (sim::LolaCodecLink): float32 values, LoLA's units and clock, as over the socket.
  void route_through_lola_packets(int robot);

  // Called at every control frame of robot `i`, after its controller ran (Simulation's
  // FrameObserver): how recorders and sweeps watch a run without replacing its controller.
  using FrameObserver = sim::Simulation::FrameObserver;
  void set_frame_observer(int robot, FrameObserver observer);

 private:
  void attach_controllers();

  ModuleRegistry registry_;
  std::unique_ptr<sim::Simulation> sim_;
  std::vector<std::shared_ptr<const model::RobotModel>> models_;
  std::vector<bool> through_packets_;
  // Per robot with a controller: its torso's world pose at the frame, logged beside the blackboard.
  std::vector<std::unique_ptr<Slot>> poses_;
  struct Controller;  // one robot's: its links, runtime, and what the simulation calls
  std::vector<std::unique_ptr<Controller>> controllers_;  // per robot; null: none
};

}  // namespace stride::console
