#pragma once
// What robot-side console commands act on: get, set, mr, dr, watch, plot, log start/stop/save,
// report, expect, wait, run. The same whether the robot is simulated in this process
// (LocalTarget) or runs elsewhere behind a debug server (RemoteTarget), so scripts run unchanged
// against either. Methods throw stride::Error with a one-line message and change nothing on error.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "robot/framework/module.hpp"
#include "robot/framework/plan.hpp"
#include "robot/framework/type_desc.hpp"

namespace stride::console {

// What the debug requests of the target's modules emitted since the last take_debug_output().
struct DebugOutput {
  std::vector<std::string> lines;  // "request: text"
  std::string stop;                // non-empty: a request asks to pause the run, saying why
};

class RobotTarget {
 public:
  virtual ~RobotTarget() = default;

  virtual std::string name() const = 0;  // e.g. "local nao_stand_controlled", "robot nao at ..."
  virtual bool loaded() const = 0;       // a scene is loaded / the connection is up

  // Lets the robot's time pass for up to `steps` steps (a simulation: physics steps it takes; a
  // robot: control frames it waits for); after each one calls `after_step`, which returns false
  // to stop early. Returns the steps done.
  virtual std::uint64_t advance(std::uint64_t steps, const std::function<bool()>& after_step) = 0;
  virtual double step_seconds() const = 0;
  virtual std::string time_text() = 0;  // the clock watch lines start with ("t=")
  // The keys that will be read after every step of the next advances (watch, plot, wait):
  // a remote robot streams them instead of being asked each time.
  virtual void observe(const std::vector<std::string>& keys) {}
  // Stream samples the robot dropped for this console so far (a slow reader); 0 locally.
  virtual std::uint64_t samples_dropped() const { return 0; }

  // Values: representation:X[.path], module:X[.path], provider:<Rep>, override:<Rep> (the held
  // assignments), debug:<request>.<value>, robot.name, and on a simulation also sim.*,
  // robot.torso.*, robot.fell, robot.com.*.
  virtual std::string get(const std::string& key) = 0;
  virtual const TypeDesc& type_of(const std::string& key) = 0;
  // A representation's fields are held (re-applied every frame) until `set <rep> unchanged`.
  virtual void set(const std::string& key, const std::string& fields) = 0;

  virtual std::vector<std::string> representations() = 0;
  virtual std::vector<std::string> parameter_modules() = 0;
  virtual std::string provider_of(const std::string& representation) = 0;
  virtual std::vector<std::string> providers_available(const std::string& representation) = 0;
  virtual void swap_provider(const std::string& representation, const std::string& module) = 0;
  // Every representation with its provider and the modules that could provide it, in one look
  // (a remote robot answers it in one `list`, not one per representation).
  struct Providers {
    std::vector<std::string> representations, providers;
    std::vector<std::vector<std::string>> available;
    std::string provider_of(const std::string& representation) const;  // "" if not there
  };
  virtual Providers providers();
  // What every module requires and provides; nullopt when the robot does not say (a debug
  // server from before the module graph was in its `list`).
  virtual std::optional<std::vector<ModuleDeclaration>> module_declarations() = 0;
  virtual std::vector<std::pair<std::string, DebugSwitch>> debug_requests() = 0;
  virtual void set_debug_request(const std::string& name, DebugSwitch state) = 0;
  // Called after every step of an advance: the debug output of the frames since the last call.
  virtual DebugOutput take_debug_output() = 0;

  // Logs recorded by the robot: `path` is where the robot writes (a plain name in a remote
  // robot's log directory). log_save copies a log the robot recorded to `destination` here and
  // returns what it did, for the console to print.
  virtual void log_start(const std::string& path) = 0;
  virtual void log_stop() = 0;
  virtual std::string log_save(const std::string& path, const std::string& destination) = 0;

  virtual std::string report_text() = 0;
  virtual std::string report_json() = 0;
};

}  // namespace stride::console
