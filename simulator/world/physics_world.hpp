#pragma once
// A physics engine's world: static environment, robots, one step of rigid-body dynamics with
// contacts. ODE (world/ode/) is the default; MuJoCo (world/mujoco/) the optional second engine.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "robot/model/link_poses.hpp"
#include "robot/model/robot_model.hpp"
#include "simulator/scene/scene_description.hpp"
#include "simulator/world/contact_record.hpp"

namespace stride::sim {

class RobotBody;

class PhysicsWorld {
 public:
  explicit PhysicsWorld(const PhysicsSettings& physics) : physics_(physics) {}
  virtual ~PhysicsWorld() = default;
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  const PhysicsSettings& settings() const { return physics_; }
  virtual const char* engine_name() const = 0;

  virtual void add_static_box(const StaticBox& box) = 0;
  // Seeded tiles, each one static box (an engine may hold them in a form it collides faster,
  // with the same boxes).
  virtual void add_uneven_patch(const UnevenPatch& patch, std::uint64_t seed);
  // A robot with its root link at `root_pose` and joints at `q` (mimic applied); it stays owned
  // by the caller and must be destroyed before the world.
  virtual std::unique_ptr<RobotBody> add_robot(const model::RobotModel& model, int robot_index,
                                               const Eigen::Isometry3d& root_pose,
                                               const model::JointVector& q) = 0;

  // Step the dynamics by settings().step and keep the contacts for sensors.
  virtual void step() = 0;
  const std::vector<ContactRecord>& contacts() const { return contacts_; }
  virtual int static_geom_count() const = 0;

 protected:
  PhysicsSettings physics_;
  std::vector<ContactRecord> contacts_;
};

// The tiles of an uneven patch as static boxes (what add_uneven_patch adds), and the seed a
// scene's patch `i` is built with.
std::vector<StaticBox> uneven_tiles(const UnevenPatch& patch, std::uint64_t seed);
std::uint64_t uneven_patch_seed(const SceneDescription& scene, std::size_t i);

// The world of the engine `physics` names; throws stride::Error if that engine is not built in.
std::unique_ptr<PhysicsWorld> make_physics_world(const PhysicsSettings& physics,
                                                 const GroundSettings& ground);

}  // namespace stride::sim
