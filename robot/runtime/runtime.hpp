#pragma once
// The robot's frame loop: owns the representations (blackboard), the planned modules and the
// hardware link. One step():
//   link.read(SensorFrame) -> FrameInfo -> modules in dependency order -> ActuatorFrame ->
//   link.write
// SensorFrame, FrameInfo, ModuleTimes and CommandSafety are written by the Runtime;
// ActuatorFrame must be provided by a module (e.g. ActuatorConversion from JointRequest). The
// command goes through the CommandGuard (limits, NaN hold) on its way to the link.
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "robot/framework/module_registry.hpp"
#include "robot/framework/plan.hpp"
#include "robot/hal/hardware_link.hpp"
#include "robot/representations/command_safety.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/hal_reflection.hpp"
#include "robot/runtime/command_guard.hpp"
#include "robot/runtime/frame_boundary.hpp"
#include "robot/runtime/log.hpp"
#include "robot/runtime/runtime_config.hpp"

namespace stride {

class RuntimeEvents;
struct InertialSensorData;
struct SensorConversionParameters;

class Runtime {
 public:
  // Instantiates every registered module once to learn its declarations, applies the configured
  // parameters, then plans. Throws stride::Error on any configuration error.
  Runtime(const ModuleRegistry& registry, RuntimeConfig config, hal::HardwareLink& link);
  ~Runtime();
  Runtime(const Runtime&) = delete;
  Runtime& operator=(const Runtime&) = delete;

  // One frame. False (and nothing run) when the link reports it is lost. A module's exception
  // leaves step() or, with ModuleErrorPolicy::Hold, makes the frame send the last safe command.
  bool step();

  // Module exceptions caught under ModuleErrorPolicy::Hold: one entry per module, in the order
  // they first failed.
  struct ModuleFault {
    std::string module;
    std::string message;     // the first one
    std::int64_t frame = 0;  // where it first failed
    std::int64_t count = 0;  // frames it failed in
  };
  const std::vector<ModuleFault>& module_faults() const { return faults_; }
  // The command the link was last given (after the guard).
  const hal::ActuatorFrame& last_command() const { return guard_.last_safe(); }
  const model::RobotModel* robot_model() const { return config_.model.get(); }

  const std::vector<std::string>& module_order() const { return order_; }
  // What every registered module requires and provides (running or not), in registry order.
  const std::vector<ModuleDeclaration>& module_declarations() const { return declarations_; }
  std::string provider_of(const std::string& representation) const;  // "" for built-ins
  std::vector<std::string> providers_available(const std::string& representation) const;
  // Chooses `module` (or "default": the configured choice) for `representation` and re-plans
  // between frames; module state is kept where a module's role did not change.
  // Throws, naming the known choices, when no module provides `representation` or `module`
  // (unless "default") is not one of them.
  void swap_provider(const std::string& representation, const std::string& module);

  // Parameters as text, e.g. set_parameters("Stand", "knee_pitch=0.5 hip_pitch=-0.2").
  void set_parameters(const std::string& module, std::string_view text);

  // Console keys: "representation:<Name>[.path]" and "module:<Name>[.path]" (parameters).
  std::string get(std::string_view key) const;
  // A module's parameters change once. A representation's fields are set now and held: re-applied
  // every frame right after its provider (or the runtime, for built-ins) writes it, until
  // set(key, "unchanged") releases the representation (SimRobot's convention).
  void set(std::string_view key, std::string_view text);
  // Held representation overrides: name -> the field assignments, in the order they were set.
  const std::map<std::string, std::string, std::less<>>& overrides() const { return overrides_; }
  const TypeDesc& type_of(std::string_view key) const;
  std::vector<std::string> representation_names() const;  // blackboard order
  std::vector<std::string> parameter_modules() const;
  // The parameters `module` runs with (typed access: slot_value), or nullptr if it has none.
  const Slot* parameters_of(std::string_view module) const;

  // Debug requests: named switches modules register and test with DebugRequest::on().
  std::vector<std::pair<std::string, DebugSwitch>> debug_requests() const;
  void set_debug_request(const std::string& name, DebugSwitch state);
  // What the debug requests emitted: lines since the last call (and how many were dropped), the
  // latest plotted values ("request.value"), the first stop reason since the last call ("" none).
  std::vector<std::string> take_debug_lines();
  const std::map<std::string, double, std::less<>>& debug_values() const { return debug_.values; }
  std::string take_debug_stop();

  // What runs now: every representation's provider and every parameter's value, as text.
  RuntimeConfig running_config() const;

  // Logs every representation on the blackboard every frame (see log.hpp), with running_config()
  // (recorded_config.hpp) and `metadata` (e.g. the robot's name) in the log's header.
  void start_log(const std::string& path, const LogMetadata& metadata = {});
  // Such a log as a writer of its own, for a recorder beside the runtime's (a debug client's log).
  std::unique_ptr<LogWriter> open_log(const std::string& path,
                                      const LogMetadata& metadata = {}) const;
  void stop_log();
  // Logged with every frame after the blackboard's representations, under `name`, without being
  // on the blackboard (a simulation's SimulatedTorsoPose). Not owned; outlives this runtime's logs.
  void log_also(std::string name, const Slot* slot) {
    log_also_.emplace_back(std::move(name), slot);
  }
  bool logging() const { return log_ != nullptr; }
  std::size_t logged_frames() const;  // frames in the log being recorded (0 without one)
  // Under LogErrorPolicy::StopLogging: why the last log ended by itself (a full disk), as one
  // line; "" while logging or after a log stopped on request. The frames before stay readable.
  const std::string& log_stopped() const { return log_stopped_; }

  // Called at the end of every step (nullptr: none). Not owned. The boundary it replaces is told
  // (FrameBoundary::detached): set nullptr before destroying a runtime a boundary outlives.
  void set_frame_boundary(FrameBoundary* boundary) {
    if (boundary_ && boundary_ != boundary) boundary_->detached(*this);
    boundary_ = boundary;
  }
  // Counts re-plans: the blackboard may have new representations after one.
  std::uint64_t plan_generation() const { return plan_generation_; }
  // Puts frame `frame` of a log onto the blackboard (for `log goto`); returns the names skipped
  // because they are not on this blackboard or have another type.
  std::vector<std::string> load_frame(const LogReader& log, std::size_t frame);

  template <class T>
  const T& representation() const {
    return slot_value<T>(typed_slot(Reflect<T>::type_name(), typeid(T)));
  }
  const Slot& representation_slot(const std::string& name) const;
  const Slot& parameter_slot_of(const std::string& module) const;  // throws naming the module

 private:
  class Context;
  struct ModuleEntry;
  friend class Context;

  Slot& blackboard_slot(std::string_view name, std::type_index type,
                        std::unique_ptr<Slot> (*make)());
  const Slot& typed_slot(std::string_view name, std::type_index type) const;
  Slot& parameter_slot(const std::string& module);
  int debug_request_index(std::string_view name);
  void check_provider_choice(const std::string& representation, const std::string& module) const;
  void apply_override(const std::string& representation, const std::string& text);
  void apply_overrides_of(const std::set<std::string>& representations);
  void replan(const std::map<std::string, std::string>& chosen);
  bool run_modules();  // false: a module threw and the policy holds
  void record_fault(const std::string& module, const char* what);
  void say_events();  // the frame's events as console lines (robot/runtime/runtime_events.hpp)
  void say(std::string line);  // a console line, counted as dropped beyond kMaxDebugLines

  const ModuleRegistry& registry_;
  RuntimeConfig config_;
  hal::HardwareLink& link_;

  std::vector<std::unique_ptr<Slot>> slots_;  // blackboard, creation order
  std::map<std::string, Slot*, std::less<>> by_name_;
  std::vector<std::pair<std::string, const Slot*>> log_also_;             // beside the blackboard
  std::map<std::string, std::unique_ptr<Slot>, std::less<>> parameters_;  // module -> parameters
  std::vector<ModuleDeclaration> declarations_;
  std::map<std::string, std::string> chosen_;  // current provider choices
  ModulePlan plan_;
  std::vector<std::unique_ptr<ModuleEntry>> modules_;
  std::vector<std::string> order_;

  DebugChannel debug_;
  std::map<std::string, std::string, std::less<>> overrides_;  // representation -> assignments

  hal::SensorFrame* sensor_ = nullptr;
  FrameInfo* frame_info_ = nullptr;
  ModuleTimes* times_ = nullptr;
  hal::ActuatorFrame* actuator_ = nullptr;
  CommandSafety* safety_ = nullptr;
  CommandGuard guard_;
  hal::ActuatorFrame command_;         // what goes to the link this frame
  model::RobotModel declaring_model_;  // handed out while learning declarations without a model
  std::vector<ModuleFault> faults_;
  std::int64_t frame_counter_ = 0;
  std::unique_ptr<LogWriter> log_;
  std::string log_stopped_;
  FrameBoundary* boundary_ = nullptr;
  std::uint64_t plan_generation_ = 0;
  std::unique_ptr<RuntimeEvents> events_;
  const InertialSensorData* inertial_ = nullptr;             // null: no IMU on the blackboard
  const SensorConversionParameters* fall_params_ = nullptr;  // null: the default fall_tilt
};

}  // namespace stride
