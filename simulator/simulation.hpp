#pragma once
// A scene brought to life: the physics world, its robots and their devices, timed pushes, and the
// control-frame clock that controllers attach to. step() is the one place that says what happens
// in a frame, in order (docs/architecture.md "One frame").
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robot/hal/frame_controller.hpp"
#include "simulator/landing_metrics.hpp"
#include "simulator/scene/scene_description.hpp"
#include "simulator/simulated_robot.hpp"
#include "simulator/walk_metrics.hpp"
#include "simulator/world/physics_world.hpp"

namespace stride::sim {

struct ActivePush {
  int robot = 0;
  int link = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d at = Eigen::Vector3d::Zero();  // link frame
  double start = 0, end = 0;
};

// Throws stride::Error("push: force 1e+308 N outside [-1e+07, 1e+07]") for a push beyond the
// limits (robot/core/physical_limits.hpp): |force| per axis, application point, duration.
void check_push(const Eigen::Vector3d& force, const Eigen::Vector3d& at, double duration);

class Simulation {
 public:
  // Builds everything from `scene`; throws stride::Error (file:line) and leaves nothing behind.
  explicit Simulation(SceneDescription scene);
  ~Simulation();

  static std::unique_ptr<Simulation> from_file(const std::string& path,
                                               std::optional<std::uint64_t> seed = std::nullopt);

  // Rebuilds the world from the same description: the same run follows, bit for bit.
  void reset();

  // One physics step, and the control frame of every robot whose frame closes with it: sense,
  // the controller's frame, actuate, record (simulation.cpp says it in that order).
  void step();
  // Steps for `seconds`; `after_step`, if given, is called after every physics step.
  void run_for(double seconds, const std::function<void()>& after_step = {});

  double time() const { return static_cast<double>(steps_) * scene_.physics.step; }
  std::uint64_t steps() const { return steps_; }
  const SceneDescription& scene() const { return scene_; }
  PhysicsWorld& world() { return *world_; }
  const PhysicsWorld& world() const { return *world_; }
  int robot_count() const { return static_cast<int>(robots_.size()); }
  SimulatedRobot& robot(int i) { return *robots_[i]; }
  const SimulatedRobot& robot(int i) const { return *robots_[i]; }
  int robot_index(const std::string& name) const;  // -1 if absent

  // The controller of robot `i` (not owned; nullptr: none, the servos hold their commands): at
  // each of the robot's control frames it gets the frame's sensors and gives the commands back.
  void set_controller(int robot, hal::FrameController* controller) {
    controllers_.at(robot) = controller;
  }
  // Called at every control frame of robot `i` after its controller: how recorders and sweeps
  // watch a run. Kept across reset().
  using FrameObserver = std::function<void(SimulatedRobot&)>;
  void set_frame_observer(int robot, FrameObserver observer) {
    observers_.at(robot) = std::move(observer);
  }

  // A force on a robot's link for `duration` seconds from now. Throws if the link is unknown or
  // a value is outside the limits (check_push).
  void push(const std::string& robot, const std::string& link, const Eigen::Vector3d& force,
            const Eigen::Vector3d& at, double duration);

  // Walking figures of robot `i` since the scene (re)started.
  const WalkMetrics& walk_metrics(int robot) const { return walk_metrics_[robot]; }
  const LandingMetrics& landing_metrics(int robot) const { return landing_metrics_[robot]; }

  // FNV-1a over every body's state and the robots' latest sensor frames.
  std::uint64_t state_hash() const;

 private:
  void build();
  static void check_scene_size(const RobotPlacement& placement, const model::RobotModel& m,
                               int& bodies, int& geoms);
  void apply_pushes();
  void check_inputs() const;
  void check_finite() const;

  SceneDescription scene_;
  std::unique_ptr<PhysicsWorld> world_;
  std::vector<std::unique_ptr<SimulatedRobot>> robots_;
  std::vector<int> steps_per_frame_;
  std::vector<hal::FrameController*> controllers_;
  std::vector<FrameObserver> observers_;
  std::vector<hal::ActuatorFrame> commands_;  // per robot: its controller's latest frame
  std::vector<WalkMetrics> walk_metrics_;
  std::vector<LandingMetrics> landing_metrics_;
  std::vector<ActivePush> pushes_;
  std::uint64_t steps_ = 0;
};

}  // namespace stride::sim
