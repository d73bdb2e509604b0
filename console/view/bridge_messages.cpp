// The messages the bridge builds from its target: hello, scene, frame (with samples) and tree
// (PROTOCOL.md), and when a frame is due.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "console/build_revision.hpp"
#include "console/interpreter/interpreter.hpp"
#include "console/view/kinematic_frame.hpp"
#include "console/view/robot_frame.hpp"
#include "console/view/scene_message.hpp"
#include "console/view/type_desc_json.hpp"
#include "console/view/view_bridge.hpp"
#include "console/view/walk_plan_overlay.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/model/urdf_loader.hpp"

namespace stride::view {

namespace {

constexpr auto kFrameInterval = std::chrono::microseconds(1000000 / 60);
constexpr std::size_t kMaxRows = 10000;  // samples kept while no frame goes out
constexpr double kFallTilt = 0.8;        // rad, the scenes' default fall tilt
const char* const kJointsKey = "representation:JointSensorData.position";
const char* const kAnglesKey = "representation:InertialSensorData.angles";
const char* const kModulesKey = "representation:ModuleTimes.modules";
const char* const kTimesKey = "representation:ModuleTimes.ns";

// The local simulation when it is what the console acts on and has a scene, else null.
sim::Simulation* local_simulation(console::Interpreter& in) {
  console::LocalTarget& local = in.local();
  if (&in.target() != static_cast<console::RobotTarget*>(&local) || !local.loaded()) return nullptr;
  return &local.session().simulation();
}

// Whether the walk's plan is what moves the robot: WalkPlan's provider is among the modules that
// JointRequest's provider depends on (after `mr JointRequest Stand` a walk may still run and plan,
// but its plan is not what the robot does, so it is not drawn).
bool plan_drives_joints(console::RobotTarget& t, const console::RobotTarget::Providers& p) {
  const auto decls = t.module_declarations();
  if (!decls) return true;  // an older robot does not say: drawn as before
  const std::string planner = p.provider_of("WalkPlan");
  if (planner.empty() || planner.starts_with('(')) return false;  // built in: nobody plans
  std::vector<std::string> todo{p.provider_of("JointRequest")};
  std::set<std::string> seen;
  while (!todo.empty()) {
    const std::string m = todo.back();
    todo.pop_back();
    if (m == planner) return true;
    if (!seen.insert(m).second) continue;
    const auto it = std::find_if(decls->begin(), decls->end(),
                                 [&](const ModuleDeclaration& d) { return d.name == m; });
    if (it == decls->end()) continue;
    for (const std::string& r : it->requires_) todo.push_back(p.provider_of(r));
  }
  return false;
}

}  // namespace

double ViewBridge::time() {
  if (mode_ == "log" && log_frame_) {  // the shown log frame's own clock
    try {
      return parse_number(value("representation:FrameInfo.time"), "time");
    } catch (const Error&) {
      return 0;
    }
  }
  if (sim::Simulation* s = local_simulation(interpreter_)) return s->time();
  try {
    return parse_number(interpreter_.target().time_text(), "time");
  } catch (const Error&) {
    return 0;
  }
}

std::uint64_t ViewBridge::step_count() {
  if (sim::Simulation* s = local_simulation(interpreter_)) return s->steps();
  const double dt = interpreter_.target().step_seconds();
  return dt > 0 ? static_cast<std::uint64_t>(std::llround(time() / dt)) : 0;
}

int ViewBridge::steps_per_frame() {
  sim::Simulation* s = local_simulation(interpreter_);
  if (!s) return 1;  // a robot's steps are its control frames
  if (s->robot_count() == 0) return 0;
  return static_cast<int>(std::lround(s->robot(0).period() / s->scene().physics.step));
}

Json ViewBridge::hello() {
  const double period = interpreter_.target().step_seconds() * std::max(1, steps_per_frame());
  return {{"type", "hello"},
          {"mode", mode_},
          {"target", interpreter_.target().name()},
          {"version", std::string(console::build_revision())},
          {"paused", !interpreter_.running()},
          {"realtime", interpreter_.realtime()},
          {"period", period},
          {"log_frames", log_frames_}};
}

Json ViewBridge::scene() {
  sim::Simulation* s = local_simulation(interpreter_);
  if (kinematic()) {
    const model::RobotModel* m = kinematic_model();
    std::vector<SceneRobot> robots;
    if (m) robots.push_back({s ? s->robot(0).name() : interpreter_.target().name(), m});
    return scene_message(s ? s->scene().name : interpreter_.target().name(),
                         s ? &s->scene() : nullptr, robots);
  }
  if (s) {
    std::vector<SceneRobot> robots;
    for (int i = 0; i < s->robot_count(); ++i)
      robots.push_back({s->robot(i).name(), &s->robot(i).model()});
    return scene_message(s->scene().name, &s->scene(), robots);
  }
  return scene_message(interpreter_.target().name(), nullptr, {});
}

bool ViewBridge::kinematic() {
  return mode_ == "log" || !local_simulation(interpreter_);
}

const model::RobotModel* ViewBridge::kinematic_model() {
  if (sim::Simulation* s = local_simulation(interpreter_))
    return s->robot_count() > 0 ? &s->robot(0).model() : nullptr;
  if (!shipped_model_)
    shipped_model_ = std::make_unique<model::RobotModel>(
        model::load_urdf(data_file("scenes/robots/nao/nao.urdf")));
  return shipped_model_.get();
}

void ViewBridge::observe_keys() {
  std::vector<std::string> keys = watch_keys_;
  try {
    const console::RobotTarget::Providers p = interpreter_.target().providers();
    const auto& reps = p.representations;
    walk_plan_ = std::find(reps.begin(), reps.end(), "WalkPlan") != reps.end() &&
                 plan_drives_joints(interpreter_.target(), p);
  } catch (const Error&) {
    walk_plan_ = false;  // no scene, or a robot that cannot say
  }
  if (kinematic()) keys.insert(keys.end(), {kJointsKey, kAnglesKey});
  if (kinematic() && !times_pages_.empty()) keys.insert(keys.end(), {kModulesKey, kTimesKey});
  if (kinematic() && walk_plan_) keys.push_back(kWalkPlanKey);  // streamed with the frame
  interpreter_.set_observed_extra(std::move(keys));
}

void ViewBridge::add_walk_plan(RobotFrame& f, const model::RobotModel& model, bool sensed_only) {
  if (!walk_plan_) return;
  try {
    if (auto plan = read_walk_plan(value(kWalkPlanKey))) {
      if (sensed_only) stand_on_plan(f, model, *plan);  // no world pose: where its plan goes
      place_walk_plan(f, model, *plan);
    }
  } catch (const Error&) {
    // not on the blackboard (any more): nothing planned to draw
  }
}

Json ViewBridge::robots_json() {
  Json robots = Json::array();
  sim::Simulation* s = local_simulation(interpreter_);
  if (!kinematic()) {
    for (int i = 0; s && i < s->robot_count(); ++i) {
      RobotFrame f = simulated_robot_frame(*s, i);
      if (s->robot(i).name() == interpreter_.local().selected_robot())
        add_walk_plan(f, s->robot(i).model(), false);  // the console's values are this robot's
      robots.push_back(robot_frame_json(f));
    }
    return robots;
  }
  const model::RobotModel* m = kinematic_model();
  if (!m) return robots;
  try {
    const std::vector<double> angles = numbers(value(kAnglesKey));
    if (angles.size() != 2) return robots;
    const std::string name = s ? s->robot(0).name() : interpreter_.target().name();
    const auto joints = named_numbers(value(kJointsKey));
    const std::optional<Eigen::Isometry3d> torso = logged_torso();
    RobotFrame f = torso ? posed_robot_frame(*m, name, joints, *torso)
                         : kinematic_robot_frame(*m, name, joints, angles[0], angles[1]);
    f.fell = std::abs(angles[0]) > kFallTilt || std::abs(angles[1]) > kFallTilt;
    add_walk_plan(f, *m, !torso);  // a logged pose is where it was; else it stands on its plan
    robots.push_back(robot_frame_json(f));
  } catch (const Error&) {
    // a robot without those representations is drawn without its body
  }
  return robots;
}

// The shown log frame's torso pose, where the log recorded one (a simulation's); else nothing.
std::optional<Eigen::Isometry3d> ViewBridge::logged_torso() {
  if (mode_ != "log" || !log_frame_) return std::nullopt;
  try {
    auto number = [&](const char* key) { return parse_number(value(key), key); };
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translate(
        Eigen::Vector3d(number("robot.torso.x"), number("robot.torso.y"), number("robot.torso.z")));
    t.rotate(Eigen::AngleAxisd(number("robot.torso.yaw"), Eigen::Vector3d::UnitZ()) *
             Eigen::AngleAxisd(number("robot.torso.pitch"), Eigen::Vector3d::UnitY()) *
             Eigen::AngleAxisd(number("robot.torso.roll"), Eigen::Vector3d::UnitX()));
    return t;
  } catch (const Error&) {
    return std::nullopt;  // a robot's log, or one recorded before poses were
  }
}

// Each module's time in the last frame, ms (the runtime's ModuleTimes); {} if unknown or no page
// shows them.
Json ViewBridge::module_times() {
  Json times = Json::object();
  if (times_pages_.empty()) return times;
  try {
    const std::vector<double> ns = numbers(value(kTimesKey));
    const std::vector<std::string> names = strings(value(kModulesKey));
    for (std::size_t i = 0; i < ns.size() && i < names.size(); ++i) times[names[i]] = ns[i] / 1e6;
  } catch (const Error&) {
    // a target without module times (no controller)
  }
  return times;
}

Json ViewBridge::frame(bool with_samples) {
  Json robots = robots_json();
  Json rows = Json::array();
  if (with_samples) {
    for (const auto& r : rows_) {
      Json row = Json::array();
      for (double v : r) row.push_back(std::isfinite(v) ? Json(v) : Json(nullptr));
      rows.push_back(std::move(row));
    }
    rows_.clear();
  }
  const int spf = std::max(1, steps_per_frame());
  return {
      {"type", "frame"},
      {"seq", seq_++},
      {"t", time()},
      {"frame", step_count() / static_cast<std::uint64_t>(spf)},
      {"running", interpreter_.running()},
      {"realtime", interpreter_.realtime()},
      {"log_frame", log_frame_ ? Json(*log_frame_) : Json(nullptr)},
      {"wall", std::chrono::duration<double, std::milli>(
                   last_step_wall_.value_or(std::chrono::system_clock::now()).time_since_epoch())
                   .count()},
      {"robots", std::move(robots)},
      {"samples", {{"keys", watch_keys_}, {"rows", std::move(rows)}}},
      {"times", module_times()}};
}

void ViewBridge::sample() {
  if (watch_keys_.empty()) return;
  if (rows_.size() >= kMaxRows) rows_.pop_front();
  std::vector<double> row{time()};
  for (const std::string& key : watch_keys_) {
    double v = std::nan("");
    try {
      const std::string text = value(key);
      v = text == "true" ? 1.0 : text == "false" ? 0.0 : parse_number(text, key);
    } catch (const Error&) {
    }
    row.push_back(v);
  }
  rows_.push_back(std::move(row));
}

void ViewBridge::send_frame_if_due(bool force) {
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - last_frame_ < kFrameInterval) return;
  const std::uint64_t steps = step_count();
  const bool running = interpreter_.running();
  if (!force && steps == last_steps_ && running == last_running_) return;
  last_frame_ = now;
  last_steps_ = steps;
  last_running_ = running;
  if (server_.clients() == 0) return void(rows_.clear());
  check_events();
  server_.broadcast_frame(dump(frame(true)));
}

void ViewBridge::check_events() {
  sim::Simulation* s = local_simulation(interpreter_);
  const bool fell = s && s->robot_count() > 0 && s->robot(0).fallen();
  if (fell && !fell_) event("fall", s->robot(0).name() + " fell");
  fell_ = fell;
  const Runtime* rt = s ? interpreter_.local().session().runtime(0) : nullptr;
  const std::size_t faults = rt ? rt->module_faults().size() : 0;
  for (std::size_t i = std::min(faults_, faults); i < faults; ++i) {
    const Runtime::ModuleFault& f = rt->module_faults()[i];
    event("module_fault",
          f.module + " failed at frame " + std::to_string(f.frame) + ": " + f.message);
  }
  faults_ = faults;
  if (rt && rt->plan_generation() != plan_generation_) {  // an `mr` typed anywhere
    plan_generation_ = rt->plan_generation();
    observe_keys();
  }
}

namespace {
// Each module's declaration by name; none when the target does not say (an older robot).
std::map<std::string, const ModuleDeclaration*> by_name(
    const std::optional<std::vector<ModuleDeclaration>>& decls) {
  std::map<std::string, const ModuleDeclaration*> out;
  if (decls)
    for (const ModuleDeclaration& d : *decls) out.emplace(d.name, &d);
  return out;
}

// Representation -> the modules that require it (from the declarations).
std::map<std::string, Json> required_by(const std::optional<std::vector<ModuleDeclaration>>& d) {
  std::map<std::string, Json> out;
  if (d)
    for (const ModuleDeclaration& m : *d)
      for (const std::string& r : m.requires_) out[r].push_back(m.name);
  return out;
}
}  // namespace

Json ViewBridge::tree() {
  console::RobotTarget& t = interpreter_.target();
  Json reps = Json::array(), modules = Json::array(), debug = Json::array();
  std::map<std::string, Json> provides;  // module -> what it provides on the blackboard
  try {
    const auto decls = t.module_declarations();
    const auto declared = by_name(decls);
    auto users = required_by(decls);
    const console::RobotTarget::Providers all = t.providers();  // one look, not three per rep
    for (std::size_t i = 0; i < all.representations.size(); ++i) {
      const std::string& r = all.representations[i];
      const std::string& provider = all.providers[i];
      if (!provider.empty()) provides[provider].push_back(r);
      Json rep = {{"name", r},
                  {"provider", provider},
                  {"available", all.available[i]},
                  {"required_by", !decls              ? Json(nullptr)
                                  : users.contains(r) ? users[r]
                                                      : Json::array()}};
      rep["fields"] = type_desc_json(t.type_of("representation:" + r));
      reps.push_back(std::move(rep));
    }
    // Every module that ran (execution order, with its time), every one with parameters, then
    // every other declared one (a provider `mr` may choose).
    const Json times = module_times();
    const std::vector<std::string> with_params = t.parameter_modules();
    std::vector<std::string> names = strings(value(kModulesKey));
    auto add = [&](const std::string& m) {
      if (std::find(names.begin(), names.end(), m) == names.end()) names.push_back(m);
    };
    for (const std::string& m : with_params) add(m);
    for (const auto& [m, d] : declared) add(m);
    for (const std::string& m : names) {
      const bool params = std::find(with_params.begin(), with_params.end(), m) != with_params.end();
      const auto d = declared.find(m);
      const bool known = d != declared.end();
      modules.push_back(
          {{"name", m},
           {"requires", known ? Json(d->second->requires_) : Json(nullptr)},
           {"provides", known                  ? Json(d->second->provides)
                        : provides.contains(m) ? provides[m]
                                               : Json::array()},
           {"params", params ? type_desc_json(t.type_of("module:" + m)) : Json(nullptr)},
           {"ms", times.contains(m) ? times[m] : Json(nullptr)}});
    }
    for (const auto& [name, state] : t.debug_requests())
      debug.push_back({{"name", name}, {"state", std::string(debug_switch_name(state))}});
    return {{"type", "tree"},
            {"representations", std::move(reps)},
            {"modules", std::move(modules)},
            {"graph", decls.has_value()},
            {"debug", std::move(debug)}};
  } catch (const Error& e) {
    return {{"type", "error"}, {"error", std::string("tree: ") + e.what()}};
  }
}

}  // namespace stride::view
