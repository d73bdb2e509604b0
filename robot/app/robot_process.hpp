#pragma once
// The robot runtime as it runs on a NAO: the configured controller on the LoLA link, with the
// safety a robot with real motors needs. Frame by frame until asked to stop:
//   LoLA packet -> Runtime (modules; a failing one holds the frame) -> CommandGuard -> LoLA answer
// The link lost (socket closed or no packet for two periods): the last command stays, the loss is
// reported at once, and after the configured timeout without the link the run ends (exit code 2).
// A peer that stops reading is a lost link (every answer has a one-period deadline); a log write
// that fails (a full disk) ends the log with one line and the loop goes on.
#include <functional>
#include <iosfwd>
#include <memory>

#include "robot/app/robot_config.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/hal/lola/lola_link.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride {

// Exit codes of `stride robot`.
enum RobotExit : int {
  kRobotStopped = 0,   // stopped on request (SIGINT/SIGTERM)
  kRobotBadInput = 1,  // configuration or command-line error: nothing ran
  kRobotLinkLost = 2,  // no LoLA link for longer than the timeout
  kRobotModuleFailed =
      3,  // a module threw and the config says on_module_error="stop", or the loop failed
};

class RobotProcess {
 public:
  // Loads the model, connects to LoLA (waiting up to connect_timeout) and builds the controller;
  // throws stride::Error naming the file or socket. `events` gets one line per event as it happens.
  RobotProcess(RobotConfig config, const ModuleRegistry& registry, std::ostream& events);
  ~RobotProcess();

  void start_log(const std::string& path) { runtime_->start_log(path); }
  // Called after every frame (a debug server's side of the loop); nullptr: none. Not owned.
  void set_frame_boundary(FrameBoundary* boundary) {
    boundary_ = boundary;
    runtime_->set_frame_boundary(boundary);
  }
  // Runs until `stop_requested()` (asked between frames) or a fault ends the run. Between frames
  // `restart_requested` (may be empty), when true, rebuilds the controller from its configuration.
  int run(const std::function<bool()>& stop_requested,
          const std::function<bool()>& restart_requested = {});
  // Before run(): answers every LoLA packet with an empty map (LoLA keeps every command as it
  // was: the robot stands as it stood) until `ready(runtime)` says go; the controller does not
  // step. False when stopped, or the link stayed lost past its timeout (run() then says why).
  bool hold_until(const std::function<bool(Runtime&)>& ready,
                  const std::function<bool()>& stop_requested);
  // What happened, for the end of a run: frames, link, safety and module counts.
  std::string summary() const;

  const Runtime& runtime() const { return *runtime_; }
  const hal::lola::LolaLink& link() const { return *link_; }

 private:
  bool link_down(double& lost_for);  // false: give up (timeout)
  void say_link_back();              // once, when a lost link answers again
  void report_frame_events();
  // The configured controller, fresh, on the same link; a simulated NAO back at its start first.
  void restart_controller(const std::function<bool()>& stop_requested);

  RobotConfig config_;
  const ModuleRegistry& registry_;
  RuntimeConfig runtime_config_;
  FrameBoundary* boundary_ = nullptr;
  std::ostream& events_;
  std::unique_ptr<hal::lola::LolaLink> link_;
  std::unique_ptr<Runtime> runtime_;
  std::size_t faults_reported_ = 0;
  std::int64_t frames_ = 0;
  std::int64_t first_packet_ = 0;  // LoLA packets before the controller's frame 0 (held ones)
  bool lost_ = false;
  std::chrono::steady_clock::time_point lost_at_;
  std::chrono::steady_clock::time_point last_error_line_{};
  std::int64_t errors_unreported_ = 0;
  bool log_stop_reported_ = false;
  std::size_t log_frames_ = 0;  // frames in the log, kept after it stopped by itself
};

}  // namespace stride
