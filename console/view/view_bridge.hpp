#pragma once
// The view's bridge: serves a console Interpreter's current target to pages (PROTOCOL.md). It
// runs on the thread that owns the interpreter: poll() between commands takes the pages'
// messages (a `cmd` runs one console line, its printed output the reply) and sends a frame when
// one is due; during an advance the interpreter's step hook samples watched keys every control
// frame and sends frames at most 60 a second. The pages never pace the target.
#include <chrono>
#include <cstdint>
#include <deque>
#include <iosfwd>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "console/view/view_json.hpp"
#include "console/view/view_message.hpp"
#include "console/view/web_server.hpp"
#include "robot/model/robot_model.hpp"

namespace stride::console {
class Interpreter;
}

namespace stride::view {

struct RobotFrame;

class ViewBridge {
 public:
  // `out` is the stream the interpreter prints to (a page's command's output is taken from it);
  // `mode` is sim, remote or log (hello's "mode"). Starts serving; throws stride::Error.
  ViewBridge(console::Interpreter& interpreter, std::ostream& out, WebServerOptions options,
             std::string mode);
  ~ViewBridge();
  ViewBridge(const ViewBridge&) = delete;
  ViewBridge& operator=(const ViewBridge&) = delete;

  std::string url() const { return server_.url(); }
  const WebServer& server() const { return server_; }
  // Pages' joins and messages, then a frame if one is due. Never blocks on a page.
  void poll();
  // A one-line event to every page (kind: fall, link_lost, module_fault, info, ...).
  void event(const std::string& kind, const std::string& text);
  // The target changed outside a page's command (a lost link): pages get its scene again.
  void refresh_scene();
  // Runs one console line as a page's `cmd` does; returns what it printed, throws on failure.
  std::string command(const std::string& line);

 private:
  void on_step();
  void on_join(std::uint64_t client, bool read_only);
  void on_message(std::uint64_t client, const std::string& text);
  void run_cmd(std::uint64_t client, const CmdRequest& c);
  std::string execute(const std::string& line, std::string& error);
  void watch(std::uint64_t client, const WatchRequest& w);
  void get(std::uint64_t client, const GetRequest& g);
  std::string value(const std::string& key);
  void note_log_command(const std::string& line, const std::string& output);

  // bridge_messages.cpp
  Json hello();
  Json scene();
  Json frame(bool with_samples);  // with: the samples since the last one (taken)
  Json tree();
  Json robots_json();
  Json module_times();
  // A robot known only by its sensors' values (remote, log): drawn from its kinematics.
  bool kinematic();
  const model::RobotModel* kinematic_model();
  void observe_keys();  // what a remote robot streams for the bridge
  // ZMP ref, footsteps; `sensed_only`: a robot without a world pose also stands on the plan.
  void add_walk_plan(RobotFrame& f, const model::RobotModel& model, bool sensed_only);
  std::optional<Eigen::Isometry3d> logged_torso();  // log mode: the shown frame's, if recorded
  double time();
  std::uint64_t step_count();
  int steps_per_frame();
  void sample();
  void send_frame_if_due(bool force);
  void check_events();  // fall, module faults
  bool start_page_run(std::uint64_t client, const CmdRequest& c);
  void answer_page_runs();
  struct PageRun {
    std::uint64_t client = 0;
    std::int64_t id = 0;
    double until = 0;  // the target's time the run ends at
  };
  std::vector<PageRun> page_runs_;  // pages waiting for their `run <seconds>` to end

  console::Interpreter& interpreter_;
  std::ostream& out_;
  std::string mode_;
  WebServer server_;
  std::set<std::uint64_t> read_only_;
  // Pages showing module times: only then does a robot stream its ModuleTimes (the names and
  // times of every module, copied by its loop each frame).
  std::set<std::uint64_t> times_pages_;
  std::vector<std::string> watch_keys_;
  std::deque<std::vector<double>> rows_;  // samples since the last frame message
  std::uint64_t seq_ = 0;
  std::chrono::steady_clock::time_point last_frame_{};
  std::uint64_t last_steps_ = ~std::uint64_t{0};  // steps at the last frame sent
  bool last_running_ = false;
  bool fell_ = false;
  std::size_t faults_ = 0;             // module faults already told
  std::uint64_t plan_generation_ = 0;  // the local runtime's module plan last looked at
  std::chrono::steady_clock::time_point last_status_{};
  std::optional<std::chrono::system_clock::time_point> last_step_wall_;  // frame.wall
  std::unique_ptr<model::RobotModel> shipped_model_;  // a remote robot's (the shipped NAO)
  std::size_t log_frames_ = 0;
  std::optional<std::size_t> log_frame_;
  bool walk_plan_ = false;  // the target has a WalkPlan (observe_keys)
};

}  // namespace stride::view
