#pragma once
// What only a simulation in this process offers: scenes, stepping, pushes, moves, sensor
// switches, pictures, and the console's log player (load, browse, export, replay through the
// scene's controller). A remote robot has none of it; the console says so in one line.
#include <cstdint>
#include <string>
#include <vector>

namespace stride::console {

struct ReplaySummary {
  std::size_t frames = 0;
  std::size_t compared = 0;             // representations compared every frame
  std::vector<std::string> mismatches;  // "frame N: Rep", first few
  std::size_t mismatch_count = 0;
  std::size_t stopped_at = 0;  // first damaged frame, where the replay stopped (0: none)
  bool stopped = false;
  std::int64_t first_frame = 0;  // the controller frame the log starts at (0: its start)
};

class SimulationTarget {
 public:
  virtual ~SimulationTarget() = default;

  virtual void load(const std::string& scene_path) = 0;
  virtual void reset() = 0;

  // The scene's robots, and the one that robot.* and framework keys, mr, dr, log, push, mv, sn
  // and the built-in views act on (the first after load).
  virtual std::vector<std::string> robot_names() = 0;
  virtual std::string selected_robot() = 0;
  virtual void select_robot(const std::string& name) = 0;

  // The log player (console-side: works whatever robot the console is connected to).
  // Loads a log; returns its summary line ("N frames: C complete, D damaged (...), T truncated").
  virtual std::string log_load(const std::string& path) = 0;
  virtual void log_export(const std::string& csv_path, const std::vector<std::string>& keys) = 0;
  // Puts a loaded log frame onto the selected robot's blackboard; returns representations skipped.
  virtual std::vector<std::string> log_goto(std::size_t frame) = 0;
  virtual ReplaySummary log_replay() = 0;
  // The loaded log's frames, representations and recorded providers (robot/runtime/
  // recorded_config.hpp).
  virtual std::vector<std::string> log_info() = 0;

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
