#pragma once
// What console commands act on. Every command goes through this interface, so the same
// interpreter drives a local simulation (LocalTarget) or, later, a robot's debug server over TCP.
// Methods throw stride::Error with a one-line message and change nothing on error.
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "robot/framework/module.hpp"
#include "robot/framework/type_desc.hpp"

namespace stride::console {

struct ReplaySummary {
  std::size_t frames = 0;
  std::size_t compared = 0;             // representations compared every frame
  std::vector<std::string> mismatches;  // "frame N: Rep", first few
  std::size_t mismatch_count = 0;
  std::size_t stopped_at = 0;  // first damaged frame, where the replay stopped (0: none)
  bool stopped = false;
};

// What the debug requests of the target's modules emitted since the last take_debug_output().
struct DebugOutput {
  std::vector<std::string> lines;  // "request: text"
  std::string stop;                // non-empty: a request asks to pause the run, saying why
};

class Target {
 public:
  virtual ~Target() = default;

  virtual std::string name() const = 0;  // e.g. "local nao_stand_controlled"
  virtual bool loaded() const = 0;
  virtual void load(const std::string& scene_path) = 0;
  virtual void reset() = 0;

  // Advances up to `steps` simulation steps; after each one calls `after_step`, which returns
  // false to stop early. Returns the steps done.
  virtual std::uint64_t advance(std::uint64_t steps, const std::function<bool()>& after_step) = 0;
  virtual double step_seconds() const = 0;

  // The scene's robots, and the one that robot.* and framework keys, mr, dr, log, push, mv, sn
  // and the built-in views act on (the first after load).
  virtual std::vector<std::string> robot_names() = 0;
  virtual std::string selected_robot() = 0;
  virtual void select_robot(const std::string& name) = 0;

  // Values: representation:X[.path], module:X[.path], sim.time, sim.steps, sim.hash,
  // robot.torso.{x,y,z,roll,pitch,yaw}, robot.fell, robot.com.{x,y,z},
  // log.frames|complete|damaged|truncated, log.mismatches, provider:<Rep>,
  // override:<Rep> (the held assignments), debug:<request>.<value>.
  virtual std::string get(const std::string& key) = 0;
  virtual const TypeDesc& type_of(const std::string& key) = 0;
  virtual void set(const std::string& key, const std::string& fields) = 0;

  virtual std::vector<std::string> representations() = 0;
  virtual std::vector<std::string> parameter_modules() = 0;
  virtual std::string provider_of(const std::string& representation) = 0;
  virtual std::vector<std::string> providers_available(const std::string& representation) = 0;
  virtual void swap_provider(const std::string& representation, const std::string& module) = 0;
  virtual std::vector<std::pair<std::string, DebugSwitch>> debug_requests() = 0;
  virtual void set_debug_request(const std::string& name, DebugSwitch state) = 0;
  virtual DebugOutput take_debug_output() = 0;

  virtual void log_start(const std::string& path) = 0;
  virtual void log_stop() = 0;
  // Loads a log; returns its summary line ("N frames: C complete, D damaged (...), T truncated").
  virtual std::string log_load(const std::string& path) = 0;
  // Puts a loaded log frame onto the blackboard; returns the representations skipped.
  virtual std::vector<std::string> log_goto(std::size_t frame) = 0;
  virtual void log_export(const std::string& csv_path, const std::vector<std::string>& keys) = 0;
  virtual ReplaySummary log_replay() = 0;
  // The loaded log's frames, representations and recorded providers (robot/runtime/
  // recorded_config.hpp).
  virtual std::vector<std::string> log_info() = 0;

  virtual std::string report_text() = 0;
  virtual std::string report_json() = 0;
  virtual void push(const std::string& body, double fx, double fy, double fz, double seconds) = 0;
  virtual void move_robot(double x, double y, double z, double yaw) = 0;
  virtual void sensor_switch(const std::string& which, bool on) = 0;

  // Pictures: `view` is a built-in view (follow, front, side, top) or a scene camera.
  virtual void snapshot(const std::string& png_path, const std::string& view) = 0;
  virtual void video_start(const std::string& dir, const std::string& view,
                           std::uint64_t every_steps) = 0;
  virtual std::uint64_t video_stop() = 0;  // frames written
};

}  // namespace stride::console
