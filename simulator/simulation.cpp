#include "simulator/simulation.hpp"

#include <cmath>
#include <cstring>
#include <sstream>

#include "robot/core/error.hpp"
#include "robot/core/physical_limits.hpp"
#include "simulator/scene/scene_limits.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::sim {
namespace {

// Pushes are bounded by limits::kMaxForce each; the sum on one body stays far below this.
constexpr double kMaxBodyLoad = 1e9;

}  // namespace

void check_push(const Eigen::Vector3d& force, const Eigen::Vector3d& at, double duration) {
  const auto bound = [](const char* what, const Eigen::Vector3d& v, double most, const char* unit) {
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(v[k]) <= most)) {
        std::ostringstream msg;
        msg << "push: " << what << " " << v[k] << " " << unit << " outside [" << -most << ", "
            << most << "]";
        throw Error(msg.str());
      }
  };
  bound("force", force, limits::kMaxForce, "N");
  bound("application point", at, limits::kMaxLength, "m");
  if (!(duration > 0 && duration <= limits::kMaxDuration)) {
    std::ostringstream msg;
    msg << "push: duration " << duration << " s outside (0, " << limits::kMaxDuration << "]";
    throw Error(msg.str());
  }
}

Simulation::Simulation(SceneDescription scene) : scene_(std::move(scene)) {
  build();
}

Simulation::~Simulation() {
  robots_.clear();  // bodies belong to the world; drop robots before it
  world_.reset();
}

std::unique_ptr<Simulation> Simulation::from_file(const std::string& path,
                                                  std::optional<std::uint64_t> seed) {
  SceneDescription scene = parse_scene_file(path);
  if (seed) scene.physics.seed = *seed;
  return std::make_unique<Simulation>(std::move(scene));
}

void Simulation::build() {
  auto world = make_physics_world(scene_.physics, scene_.ground);
  for (const auto& b : scene_.boxes) world->add_static_box(b);
  for (size_t i = 0; i < scene_.uneven.size(); ++i)
    world->add_uneven_patch(scene_.uneven[i], uneven_patch_seed(scene_, i));
  std::vector<std::unique_ptr<SimulatedRobot>> robots;
  std::vector<int> steps_per_frame;
  int bodies = 0, geoms = 0;
  for (size_t i = 0; i < scene_.robots.size(); ++i) {
    const auto& placement = scene_.robots[i];
    robots.push_back(std::make_unique<SimulatedRobot>(*world, placement, static_cast<int>(i),
                                                      scene_.physics.seed));
    check_scene_size(placement, robots.back()->model(), bodies, geoms);
    const double ratio = robots.back()->period() / scene_.physics.step;
    const int n = static_cast<int>(std::lround(ratio));
    if (n < 1 || std::abs(ratio - n) > 1e-9)
      throw error_at(placement.file, placement.line,
                     "<robot>: control period " + std::to_string(robots.back()->period()) +
                         " s is not a whole number of physics steps of " +
                         std::to_string(scene_.physics.step) + " s");
    steps_per_frame.push_back(n);
  }
  std::vector<ActivePush> pushes;
  for (const auto& p : scene_.pushes) {
    int r = -1;
    for (size_t i = 0; i < scene_.robots.size(); ++i)
      if (scene_.robots[i].name == p.robot) r = static_cast<int>(i);
    const int link = robots[r]->model().link_index(p.body);
    if (link < 0)
      throw error_at(
          p.file, p.line,
          "<push>: attribute 'body': robot '" + p.robot + "' has no link named '" + p.body + "'");
    pushes.push_back({r, link, p.force, p.at, p.start, p.start + p.duration});
  }
  // Everything built: only now replace the previous state.
  robots_.clear();
  world_ = std::move(world);
  robots_ = std::move(robots);
  steps_per_frame_ = std::move(steps_per_frame);
  controllers_.resize(robots_.size());
  observers_.resize(robots_.size());
  commands_.assign(robots_.size(), hal::ActuatorFrame());
  walk_metrics_.assign(robots_.size(), WalkMetrics());
  landing_metrics_.assign(robots_.size(), LandingMetrics());
  pushes_ = std::move(pushes);
  steps_ = 0;
}

void Simulation::check_scene_size(const RobotPlacement& placement, const model::RobotModel& m,
                                  int& bodies, int& geoms) {
  bodies += static_cast<int>(m.links.size());
  for (const auto& l : m.links) geoms += static_cast<int>(l.collisions.size());
  const auto over = [&](const char* what, int n, int most) {
    throw error_at(placement.file, placement.line,
                   "<robot name=\"" + placement.name + "\">: the scene's robots have " +
                       std::to_string(n) + " " + what + " so far (at most " + std::to_string(most) +
                       ")");
  };
  if (bodies > scene_limits::kMaxBodies) over("links", bodies, scene_limits::kMaxBodies);
  if (geoms > scene_limits::kMaxRobotGeoms)
    over("collision shapes", geoms, scene_limits::kMaxRobotGeoms);
}

void Simulation::reset() {
  build();
}

int Simulation::robot_index(const std::string& name) const {
  for (size_t i = 0; i < robots_.size(); ++i)
    if (robots_[i]->name() == name) return static_cast<int>(i);
  return -1;
}

void Simulation::push(const std::string& robot, const std::string& link,
                      const Eigen::Vector3d& force, const Eigen::Vector3d& at, double duration) {
  const int r = robot_index(robot);
  if (r < 0) throw Error("no robot named '" + robot + "'");
  const int l = robots_[r]->model().link_index(link);
  if (l < 0) throw Error("robot '" + robot + "' has no link named '" + link + "'");
  check_push(force, at, duration);
  pushes_.push_back({r, l, force, at, time(), time() + duration});
}

// One physics step and the control frames closing with it. In a robot's frame:
//   physics steps -> sense -> controller frame -> actuate -> record (-> physics steps ...)
void Simulation::step() {
  // Physics: pushes act, the servos drive toward their commands, the world integrates, the devices
  // measure what they average over a frame (currents, sole loads).
  apply_pushes();
  for (auto& r : robots_) r->before_physics_step();
  check_inputs();
  world_->step();
  ++steps_;
  for (auto& r : robots_) r->after_physics_step(*world_);
  check_finite();
  for (size_t i = 0; i < robots_.size(); ++i) {
    if (steps_ % static_cast<std::uint64_t>(steps_per_frame_[i]) != 0) continue;
    SimulatedRobot& robot = *robots_[i];
    // Sense: the frame's readings (noise, delay, quantisation as the scene switches them).
    robot.sample_sensors(time(), scene_.physics.gravity);
    // Controller frame, sensors in and commands out; actuate: the servos take the commands.
    hal::ActuatorFrame& commands = commands_[i];
    if (controllers_[i] && controllers_[i]->control_frame(robot.latest_sensors(), commands))
      robot.write(commands);
    // Record: the walk's and landings' figures from the plant's true state, then whoever watches.
    walk_metrics_[i].observe(robot);
    landing_metrics_[i].observe(robot);
    if (observers_[i]) observers_[i](robot);
  }
}

void Simulation::apply_pushes() {
  const double t = time();
  for (const ActivePush& p : pushes_) {
    if (t < p.start - 1e-12 || t >= p.end - 1e-12) continue;
    robots_[p.robot]->mutable_body().add_force(p.link, p.force, p.at);
  }
}

void Simulation::run_for(double seconds, const std::function<void()>& after_step) {
  if (const std::string p = limits::duration_problem(seconds); !p.empty()) throw Error("run: " + p);
  const auto n = static_cast<std::uint64_t>(std::llround(seconds / scene_.physics.step));
  for (std::uint64_t k = 0; k < n; ++k) {
    step();
    if (after_step) after_step();
  }
}

// What the engine is about to integrate: every force and torque on a robot body finite and bounded.
// A runaway is reported here, before an engine's own assertions could abort the process.
void Simulation::check_inputs() const {
  for (const auto& r : robots_) {
    const auto& body = r->body();
    for (int l = 0; l < body.link_count(); ++l) {
      const auto [f, t] = body.queued_load(l);
      for (int k = 0; k < 3; ++k)
        if (!(std::abs(f[k]) <= kMaxBodyLoad && std::abs(t[k]) <= kMaxBodyLoad)) {
          std::ostringstream msg;
          msg << "physics diverged at t=" << time() << " s: robot '" << r->name() << "' link '"
              << body.model().links[l].name << "' has a force of " << f[k] << " N / torque of "
              << t[k] << " N*m about to be applied (at most " << kMaxBodyLoad << ")";
          throw Error(msg.str());
        }
    }
  }
}

void Simulation::check_finite() const {
  for (const auto& r : robots_) {
    const auto& body = r->body();
    for (int l = 0; l < body.link_count(); ++l) {
      const Eigen::Vector3d p = body.link_com(l);
      const Eigen::Vector3d v = body.link_com_velocity(l);
      const Eigen::Vector3d w = body.link_angular_velocity(l);
      const char* what = nullptr;
      for (int k = 0; k < 3 && !what; ++k) {
        if (!std::isfinite(p[k]) || !std::isfinite(v[k]) || !std::isfinite(w[k]))
          what = "a non-finite state";
        else if (std::abs(v[k]) > 1e3 || std::abs(w[k]) > 1e4 || std::abs(p[k]) > 1e5)
          what = "an exploding state";
      }
      if (what) {
        std::ostringstream msg;
        msg << "physics diverged at t=" << time() << " s: robot '" << r->name() << "' link '"
            << body.model().links[l].name << "' has " << what
            << " (try a smaller step, more solver iterations or a larger cfm)";
        throw Error(msg.str());
      }
    }
  }
}

namespace {
struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
};
}  // namespace

std::uint64_t Simulation::state_hash() const {
  Fnv f;
  f.bytes(&steps_, sizeof steps_);
  for (const auto& r : robots_) {
    r->body().visit_state([&f](const double* v, int n) { f.bytes(v, sizeof(double) * n); });
    const hal::SensorFrame& s = r->latest_sensors();
    f.bytes(s.position.data(), sizeof(double) * s.position.size());
    f.bytes(s.current.data(), sizeof(double) * s.current.size());
    f.bytes(s.accelerometer.data(), sizeof(double) * 3);
    f.bytes(s.gyroscope.data(), sizeof(double) * 3);
    f.bytes(s.angles.data(), sizeof(double) * 2);
    f.bytes(s.fsr.data(), sizeof(double) * s.fsr.size());
  }
  return f.h;
}

}  // namespace stride::sim
