#pragma once
// The ODE world, its collision spaces and static environment; steps physics with contacts.
#include <deque>
#include <functional>
#include <memory>
#include <vector>

#include <ode/ode.h>

#include "simulator/scene/scene_description.hpp"
#include "simulator/world/contact_record.hpp"
#include "simulator/world/geom_info.hpp"
#include "simulator/world/self_contact_candidates.hpp"
#include "simulator/world/static_geom_grid.hpp"

namespace stride::sim {

class PhysicsWorld {
 public:
  PhysicsWorld(const PhysicsSettings& physics, const GroundSettings& ground);
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  dWorldID world() const { return world_; }
  dSpaceID robot_space() const { return robot_space_; }
  dSpaceID static_space() const { return static_space_; }
  const PhysicsSettings& settings() const { return physics_; }

  void add_static_box(const StaticBox& box);
  void add_uneven_patch(const UnevenPatch& patch, std::uint64_t seed);
  // Owned storage for geometry data, stable for the world's lifetime.
  GeomInfo* new_geom_info(const GeomInfo& info);
  // Called for two geoms of one robot; true = they may collide.
  void set_self_collision_filter(std::function<bool(const GeomInfo&, const GeomInfo&)> f) {
    self_filter_ = std::move(f);
  }

  // Collide, step the solver by settings().step, and keep the contacts for sensors.
  void step();
  const std::vector<ContactRecord>& contacts() const { return contacts_; }
  int static_geom_count() const { return static_geoms_; }

 private:
  static void near_callback(void* data, dGeomID g1, dGeomID g2);
  void collide_pair(dGeomID g1, dGeomID g2);
  void collide_with_static();
  void create_contact_joints();

  struct PendingContact {
    dContact contact;
    dBodyID b1, b2;
    const GeomInfo* i1;
    const GeomInfo* i2;
  };

  PhysicsSettings physics_;
  dWorldID world_ = nullptr;
  dSpaceID robot_space_ = nullptr;
  dSpaceID static_space_ = nullptr;
  dJointGroupID contact_group_ = nullptr;
  std::deque<GeomInfo> infos_;
  std::vector<dJointFeedback> feedback_;  // fixed capacity: pointers stay valid within a step
  std::vector<ContactRecord> contacts_;
  std::vector<PendingContact> pending_;  // this step's contacts, joined after all collisions
  std::vector<std::pair<dBodyID, int>> points_per_body_;
  std::function<bool(const GeomInfo&, const GeomInfo&)> self_filter_;
  int static_geoms_ = 0;
  SelfContactCandidates self_candidates_;        // rebuilt when the robot geom count changes
  std::unique_ptr<StaticGeomGrid> static_grid_;  // built on the first step, when all are placed
  std::vector<dGeomID> candidates_;
  unsigned long rand_state_ = 0;  // ODE's solver shuffles with a process-wide generator
};

}  // namespace stride::sim
