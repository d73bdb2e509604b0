#pragma once
// The console target in this process: a SimSession (scene + controllers), both the robot side and
// the simulation side of the console. Robot and framework keys act on the selected robot
// (`robot <name>`), the first one after load; `serve` offers that robot's controller to debug
// clients as a robot's debug server does.
#include <memory>
#include <optional>
#include <set>

#include "console/session/sim_session.hpp"
#include "console/target/robot_target.hpp"
#include "console/target/simulation_target.hpp"
#include "robot/debug/server.hpp"
#include "robot/runtime/log.hpp"
#include "robot/runtime/world_pose.hpp"
#include "simulator/render/snapshot.hpp"

namespace stride::console {

class LocalTarget : public RobotTarget, public SimulationTarget {
 public:
  LocalTarget() = default;
  explicit LocalTarget(const std::string& scene_path) { load(scene_path); }
  ~LocalTarget() override;

  std::string name() const override;
  bool loaded() const override { return session_ != nullptr; }
  void load(const std::string& scene_path) override;
  void reset() override;
  std::uint64_t advance(std::uint64_t steps, const std::function<bool()>& after_step) override;
  double step_seconds() const override;
  std::string time_text() override;
  std::vector<std::string> robot_names() override;
  std::string selected_robot() override;
  void select_robot(const std::string& name) override;

  std::string get(const std::string& key) override;
  const TypeDesc& type_of(const std::string& key) override;
  void set(const std::string& key, const std::string& fields) override;

  std::vector<std::string> representations() override;
  std::vector<std::string> parameter_modules() override;
  std::string provider_of(const std::string& representation) override;
  std::vector<std::string> providers_available(const std::string& representation) override;
  void swap_provider(const std::string& representation, const std::string& module) override;
  std::optional<std::vector<ModuleDeclaration>> module_declarations() override;
  std::vector<std::pair<std::string, DebugSwitch>> debug_requests() override;
  void set_debug_request(const std::string& name, DebugSwitch state) override;
  DebugOutput take_debug_output() override;

  void log_start(const std::string& path) override;
  void log_stop() override;
  std::string log_save(const std::string& path, const std::string& destination) override;
  std::string log_load(const std::string& path) override;
  std::vector<std::string> log_goto(std::size_t frame) override;
  // Whether the frame `log goto` shows holds the torso's world pose (a simulation's log).
  bool shown_pose_logged() const { return shown_pose_.has_value(); }
  void log_export(const std::string& csv_path, const std::vector<std::string>& keys) override;
  ReplaySummary log_replay() override;
  std::vector<std::string> log_info() override;

  std::string report_text() override;
  std::string report_json() override;
  void push(const std::string& body, double fx, double fy, double fz, double seconds) override;
  void move_robot(double x, double y, double z, double yaw) override;
  void sensor_switch(const std::string& which, bool on) override;
  void snapshot(const std::string& png_path, const std::string& view) override;
  void video_start(const std::string& dir, const std::string& view,
                   std::uint64_t every_steps) override;
  std::uint64_t video_stop() override;

  SimSession& session();
  // Physics steps per control frame of the selected robot (`watch ... every N` counts frames).
  std::uint64_t steps_per_frame();

  // Serves the selected robot's controller (`serve`); the server follows it through load and
  // reset (the first robot after a load). Throws if the robot has no controller or on a bad port.
  const debug::Endpoint& serve(debug::ServerOptions options);
  void stop_serving();
  bool serving() const { return server_ != nullptr; }
  // Answers debug clients' requests while the simulation is paused.
  void serve_idle();

 private:
  void detach_server();
  void attach_server();
  Runtime& runtime();
  sim::SimulatedRobot& robot();  // the selected one; throws without robots
  render::WorldRenderer& renderer();
  std::string sim_value(const std::string& key);
  std::string logged_robot_value(const std::string& key);

  std::unique_ptr<SimSession> session_;
  std::unique_ptr<LogReader> log_;
  std::optional<ReplaySummary> replay_;
  std::optional<std::size_t> shown_frame_;           // `log goto`: the frame on the blackboard
  std::optional<SimulatedTorsoPose> shown_pose_;     // its torso's world pose, if logged
  std::unique_ptr<render::WorldRenderer> renderer_;  // made at the first picture
  render::VideoRecorder video_;
  int selected_ = 0;       // robot index
  std::set<int> swapped_;  // robots whose providers differ from the scene's (a replay would not)
  std::unique_ptr<debug::DebugServer> server_;
  int served_ = 0;            // robot index the server is attached to
  double stepping_wall_ = 0;  // s of wall time stepping since load/reset: the report's wall time
};

}  // namespace stride::console
