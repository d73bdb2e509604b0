#include "console/target/local_target.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "console/target/logged_scene.hpp"
#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"
#include "robot/framework/value.hpp"
#include "robot/runtime/controller_keys.hpp"
#include "robot/runtime/recorded_config.hpp"
#include "robot/runtime/replay.hpp"
#include "simulator/render/png_file.hpp"
#include "simulator/render/text_overlay.hpp"
#include "simulator/report/run_report.hpp"
#include "simulator/teleport.hpp"

namespace stride::console {

namespace {
std::string number_text(double v) {
  std::ostringstream o;
  o.precision(10);
  o << v;
  return o.str();
}
}  // namespace

LocalTarget::~LocalTarget() {
  stop_serving();
}

std::string LocalTarget::name() const {
  return session_ ? "local " + session_->simulation().scene().name : "local (no scene)";
}

SimSession& LocalTarget::session() {
  if (!session_) throw Error("no scene loaded (use: load <scene.xml>)");
  return *session_;
}

sim::SimulatedRobot& LocalTarget::robot() {
  auto& sim = session().simulation();
  if (sim.robot_count() == 0) throw Error("the scene has no robot");
  return sim.robot(selected_);
}

Runtime& LocalTarget::runtime() {
  const std::string name = robot().name();
  Runtime* rt = session().runtime(selected_);
  if (!rt) throw Error("robot '" + name + "' has no <controller> in this scene");
  return *rt;
}

std::vector<std::string> LocalTarget::robot_names() {
  auto& sim = session().simulation();
  std::vector<std::string> names;
  for (int i = 0; i < sim.robot_count(); ++i) names.push_back(sim.robot(i).name());
  return names;
}

std::string LocalTarget::selected_robot() {
  return robot().name();
}

void LocalTarget::select_robot(const std::string& name) {
  const auto names = robot_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) {
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw Error("no robot '" + name +
                "' in this scene (robots: " + (known.empty() ? std::string("none") : known) + ")");
  }
  selected_ = static_cast<int>(it - names.begin());
}

void LocalTarget::load(const std::string& scene_path) {
  auto fresh = std::make_unique<SimSession>(scene_path);  // the old session stays on error
  detach_server();
  session_ = std::move(fresh);
  selected_ = served_ = 0;
  shown_frame_.reset();
  stepping_wall_ = 0;
  swapped_.clear();
  video_.stop();  // a recording belongs to the scene it started in
  attach_server();
}

void LocalTarget::reset() {
  detach_server();
  session().reset();
  shown_frame_.reset();
  stepping_wall_ = 0;
  swapped_.clear();
  attach_server();
}

std::uint64_t LocalTarget::advance(std::uint64_t steps, const std::function<bool()>& after_step) {
  auto& sim = session().simulation();
  shown_frame_.reset();  // the simulation moves on: robot.* is its robot again
  const auto t0 = std::chrono::steady_clock::now();
  std::uint64_t done = 0;
  while (done < steps) {
    sim.step();
    ++done;
    if (video_.active()) video_.after_step(renderer(), sim);
    if (after_step && !after_step()) break;
  }
  stepping_wall_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return done;
}

double LocalTarget::step_seconds() const {
  return session_ ? session_->simulation().scene().physics.step : 0.0;
}

std::string LocalTarget::time_text() {
  return number_text(session().simulation().time());
}

std::string LocalTarget::sim_value(const std::string& key) {
  if (is_controller_key(key)) return controller_value(runtime(), key);
  if (key == "log.frames" || key == "log.complete" || key == "log.damaged" ||
      key == "log.truncated") {
    if (!log_) throw Error(key + ": no log loaded (log load <file>)");
    const LogIntegrity& i = log_->integrity();
    return std::to_string(key == "log.frames"     ? log_->frame_count()
                          : key == "log.complete" ? i.complete
                          : key == "log.damaged"  ? i.damaged
                                                  : i.truncated);
  }
  if (key == "log.mismatches" || key == "log.compared" || key == "log.replayed") {
    if (!replay_) throw Error(key + ": no replay yet (log replay)");
    return std::to_string(key == "log.mismatches" ? replay_->mismatch_count
                          : key == "log.compared" ? replay_->compared
                                                  : replay_->frames);
  }
  auto& sim = session().simulation();
  if (key == "sim.time") return number_text(sim.time());
  if (key == "sim.steps") return std::to_string(sim.steps());
  if (key == "sim.hash") return sim::hash_hex(sim.state_hash());
  if (key == "robot.name") return robot().name();
  const auto& r = robot();
  if (key == "robot.fell") return r.fallen() ? "true" : "false";
  if (shown_frame_ && key.starts_with("robot.")) return logged_robot_value(key);
  const sim::TorsoPose p = r.torso_pose();
  const std::pair<const char*, double> torso[] = {
      {"robot.torso.x", p.x},       {"robot.torso.y", p.y},         {"robot.torso.z", p.z},
      {"robot.torso.roll", p.roll}, {"robot.torso.pitch", p.pitch}, {"robot.torso.yaw", p.yaw}};
  for (const auto& [k, v] : torso)
    if (key == k) return number_text(v);
  const Eigen::Vector3d com = r.body().centre_of_mass();
  if (key == "robot.com.x") return number_text(com.x());
  if (key == "robot.com.y") return number_text(com.y());
  if (key == "robot.com.z") return number_text(com.z());
  throw Error("unknown key '" + key +
              "' (sim.time|steps|hash, robot.name|fell, robot.torso.x|y|z|roll|pitch|yaw, "
              "robot.com.x|y|z, log.frames|complete|damaged|truncated|mismatches|compared|"
              "replayed, provider:, override:, debug:)");
}

// While `log goto` shows a frame, robot.torso.* keys are the logged robot's: where a simulation's
// log recorded its torso, or for a log without a world pose, what its IMU measured (position and
// yaw are then refused rather than taken from the simulation, which stands elsewhere).
std::string LocalTarget::logged_robot_value(const std::string& key) {
  if (shown_pose_) {
    const SimulatedTorsoPose& p = *shown_pose_;
    const std::pair<const char*, double> torso[] = {
        {"robot.torso.x", p.x},       {"robot.torso.y", p.y},         {"robot.torso.z", p.z},
        {"robot.torso.roll", p.roll}, {"robot.torso.pitch", p.pitch}, {"robot.torso.yaw", p.yaw}};
    for (const auto& [k, v] : torso)
      if (key == k) return number_text(v);
  } else if (key == "robot.torso.roll" || key == "robot.torso.pitch") {
    return runtime().get(std::string("representation:InertialSensorData.angles[") +
                         (key == "robot.torso.roll" ? "0" : "1") + "]");
  }
  throw Error(key + ": log frame " + std::to_string(*shown_frame_) + " is shown and " +
              (shown_pose_ ? std::string("a log holds the torso's pose only (robot.torso.*)")
                           : "this log holds no world pose (a robot's, or a simulation's recorded "
                             "before " +
                                 std::string(kWorldPoseSince) +
                                 "; robot.torso.roll|pitch come from its IMU)") +
              "; run, step or reset return to the simulation");
}

std::string LocalTarget::get(const std::string& key) {
  if (key.starts_with("representation:") || key.starts_with("module:")) return runtime().get(key);
  return sim_value(key);
}

const TypeDesc& LocalTarget::type_of(const std::string& key) {
  if (!key.starts_with("representation:") && !key.starts_with("module:"))
    throw Error("'" + key + "' has no type description (a number computed by the simulator)");
  return runtime().type_of(key);
}

void LocalTarget::set(const std::string& key, const std::string& fields) {
  runtime().set(key, fields);
}

std::vector<std::string> LocalTarget::representations() {
  return runtime().representation_names();
}
std::vector<std::string> LocalTarget::parameter_modules() {
  return runtime().parameter_modules();
}
std::string LocalTarget::provider_of(const std::string& rep) {
  return runtime().provider_of(rep);
}
std::vector<std::string> LocalTarget::providers_available(const std::string& rep) {
  return runtime().providers_available(rep);
}

std::optional<std::vector<ModuleDeclaration>> LocalTarget::module_declarations() {
  return runtime().module_declarations();
}
void LocalTarget::swap_provider(const std::string& rep, const std::string& module) {
  runtime().swap_provider(rep, module);
  if (module == "default")
    swapped_.erase(selected_);
  else
    swapped_.insert(selected_);
}
std::vector<std::pair<std::string, DebugSwitch>> LocalTarget::debug_requests() {
  return runtime().debug_requests();
}
void LocalTarget::set_debug_request(const std::string& name, DebugSwitch state) {
  runtime().set_debug_request(name, state);
}

DebugOutput LocalTarget::take_debug_output() {
  DebugOutput d;
  if (!session_) return d;
  auto& sim = session_->simulation();
  for (int i = 0; i < sim.robot_count(); ++i) {
    Runtime* rt = session_->runtime(i);
    if (!rt) continue;
    // With several robots every line says whose it is.
    const std::string who = sim.robot_count() > 1 ? sim.robot(i).name() + " " : "";
    // A served robot's debug server takes its output after every frame and keeps it for us.
    debug::DebugText taken;
    if (server_ && i == served_) taken = server_->take_kept_debug_output();
    for (auto& line : taken.lines) d.lines.push_back(who + line);
    for (auto& line : rt->take_debug_lines()) d.lines.push_back(who + line);
    std::string stop = taken.stop.empty() ? rt->take_debug_stop() : taken.stop;
    if (!stop.empty() && d.stop.empty()) d.stop = who + stop;
  }
  return d;
}

void LocalTarget::log_start(const std::string& path) {
  Runtime& rt = runtime();
  if (rt.logging()) throw Error("a log is already being recorded (log stop first)");
  rt.start_log(path);
}

void LocalTarget::log_stop() {
  Runtime& rt = runtime();
  if (!rt.logging()) throw Error("no log is being recorded");
  rt.stop_log();
}

std::string LocalTarget::log_save(const std::string& path, const std::string& destination) {
  // Logs are flushed every frame, so a copy holds every complete frame even while recording.
  copy_file_checked(path, destination);
  return "saved " + path + " as " + destination;
}

std::string LocalTarget::log_load(const std::string& path) {
  auto fresh = std::make_unique<LogReader>(path);
  log_ = std::move(fresh);
  replay_.reset();
  return log_->summary();
}

std::vector<std::string> LocalTarget::log_goto(std::size_t frame) {
  if (!log_) throw Error("no log loaded (log load <file>)");
  if (frame >= log_->frame_count())
    throw Error("frame " + std::to_string(frame) + " is outside the log's " +
                (log_->frame_count() ? "0.." + std::to_string(log_->frame_count() - 1)
                                     : std::string("frames (it has none)")));
  auto skipped = runtime().load_frame(*log_, frame);
  shown_pose_.reset();
  if (log_->index_of(SimulatedTorsoPose::kTypeName) >= 0)
    shown_pose_ = log_->read<SimulatedTorsoPose>(frame);
  shown_frame_ = frame;
  return skipped;
}

void LocalTarget::log_export(const std::string& csv_path, const std::vector<std::string>& keys) {
  if (!log_) throw Error("no log loaded (log load <file>)");
  std::ostringstream csv;
  export_csv(*log_, keys, csv);  // may throw on a bad key; nothing written then
  write_file(csv_path, csv.str());
}

ReplaySummary LocalTarget::log_replay() {
  if (!log_) throw Error("no log loaded (log load <file>)");
  runtime();  // the selected robot has a controller
  if (swapped_.count(selected_) && !has_recorded_config(log_->metadata()))
    throw Error("a provider was swapped and this log does not say which it ran with");
  const ReplayResult r =
      replay_and_compare(*log_, session().registry(),
                         recorded_config(log_->metadata(), session().runtime_config(selected_)));
  ReplaySummary s;
  s.frames = r.frames;
  s.compared = r.compared.size();
  s.mismatch_count = r.mismatches.size();
  s.stopped = r.stopped_before_damaged;
  s.stopped_at = log_->readable_prefix();
  for (std::size_t i = 0; i < r.mismatches.size() && i < 5; ++i)
    s.mismatches.push_back("frame " + std::to_string(r.mismatches[i].frame) + ": " +
                           r.mismatches[i].representation);
  // A log begun mid-run starts with module state the replay cannot know.
  if (const int fi = log_->index_of("FrameInfo"); fi >= 0 && s.frames > 0 && log_->readable(0)) {
    const Value v = log_->value(0, "FrameInfo");
    const auto [d, frame] = value_at(*log_->types()[fi].desc, v, "frame", "FrameInfo");
    if (const auto* n = std::get_if<std::int64_t>(&frame->data)) s.first_frame = *n;
  }
  replay_ = s;
  return s;
}

std::vector<std::string> LocalTarget::log_info() {
  if (!log_) throw Error("no log loaded (log load <file>)");
  return log_info_lines(*log_);
}

std::string LocalTarget::report_text() {
  return sim::run_report_text(session().simulation(), {.wall_time = stepping_wall_});
}
std::string LocalTarget::report_json() {
  return sim::run_report_json(session().simulation(), {.wall_time = stepping_wall_});
}

void LocalTarget::push(const std::string& body, double fx, double fy, double fz, double seconds) {
  const std::string name = robot().name();
  const model::RobotModel& model = robot().model();
  if (model.link_index(body) < 0) {  // the names a push takes, so the next try is right
    std::string names;
    for (const model::Link& l : model.links) names += (names.empty() ? "" : ", ") + l.name;
    throw Error("push: robot '" + name + "' has no link named '" + body + "' (its links: " + names +
                ")");
  }
  session().simulation().push(name, body, {fx, fy, fz}, Eigen::Vector3d::Zero(), seconds);
}

std::uint64_t LocalTarget::steps_per_frame() {
  const double dt = step_seconds();
  if (!loaded() || !(dt > 0) || robot_names().empty()) return 1;
  return static_cast<std::uint64_t>(std::max(1.0, std::round(robot().period() / dt)));
}

void LocalTarget::move_robot(double x, double y, double z, double yaw) {
  robot();  // throws without robots
  sim::teleport_robot(session().simulation(), selected_, {x, y, z}, yaw);
}

void LocalTarget::sensor_switch(const std::string& which, bool on) {
  auto& s = robot().sensor_switches();
  if (which == "noise")
    s.noise = on;
  else if (which == "delay")
    s.delay = on;
  else if (which == "quantise")
    s.quantise = on;
  else
    throw Error("unknown sensor switch '" + which + "' (noise, delay, quantise)");
}

render::WorldRenderer& LocalTarget::renderer() {
  if (!renderer_) renderer_ = std::make_unique<render::WorldRenderer>();
  return *renderer_;
}

void LocalTarget::snapshot(const std::string& png_path, const std::string& view) {
  if (shown_frame_) {  // the logged robot in a still copy of the scene; the run is not touched
    Runtime& rt = runtime();
    const sim::Simulation shown(logged_scene(session().simulation().scene(), selected_,
                                             robot().model(), rt.representation<JointSensorData>(),
                                             rt.representation<InertialSensorData>(), shown_pose_));
    render::RgbaImage image = render::render_view(renderer(), shown, view, selected_, false);
    render::draw_overlay(image, {"log frame " + std::to_string(*shown_frame_) + "  t " +
                                     number_text(rt.representation<FrameInfo>().time) + " s",
                                 shown_pose_ ? "torso where the log puts it"
                                             : "no world pose: on its lowest point, IMU tilt"});
    render::write_png(png_path, image);
    return;
  }
  render::write_snapshot(renderer(), session().simulation(), png_path, view, selected_);
}

void LocalTarget::video_start(const std::string& dir, const std::string& view,
                              std::uint64_t every_steps) {
  video_.start(session().simulation(), {dir}, view, every_steps, selected_);
}

std::uint64_t LocalTarget::video_stop() {
  video_.stop();
  return video_.frames();
}

const debug::Endpoint& LocalTarget::serve(debug::ServerOptions options) {
  Runtime& rt = runtime();  // the selected robot has a controller
  if (options.robot.empty()) options.robot = robot().name();
  options.keep_debug_output = true;  // this console shows the debug output too
  auto server = std::make_unique<debug::DebugServer>(std::move(options));
  stop_serving();
  server_ = std::move(server);
  served_ = selected_;
  rt.set_frame_boundary(&server_->boundary());
  return server_->endpoint();
}

void LocalTarget::stop_serving() {
  if (!server_) return;
  detach_server();
  server_.reset();
}

void LocalTarget::detach_server() {
  // The served runtime is about to go: the server lets go of it first (a client's log stops).
  if (server_ && session_ && served_ < session_->simulation().robot_count())
    if (Runtime* rt = session_->runtime(served_)) rt->set_frame_boundary(nullptr);
}

void LocalTarget::attach_server() {
  if (!server_) return;
  Runtime* rt =
      served_ < session().simulation().robot_count() ? session().runtime(served_) : nullptr;
  if (rt)
    rt->set_frame_boundary(&server_->boundary());
  else
    server_.reset();  // the new scene's robot has no controller to serve
}

void LocalTarget::serve_idle() {
  if (!server_ || !session_) return;
  if (Runtime* rt = session_->runtime(served_)) server_->idle(*rt);
}

}  // namespace stride::console
