#pragma once
// The ODE world, its collision spaces and static environment; steps physics with contacts.
#include <deque>
#include <functional>
#include <memory>
#include <vector>

#include <ode/ode.h>

#include "simulator/world/contact_law.hpp"
#include "simulator/world/geom_info.hpp"
#include "simulator/world/ode/self_contact_candidates.hpp"
#include "simulator/world/ode/static_geom_grid.hpp"
#include "simulator/world/physics_world.hpp"

namespace stride::sim {

class OdeWorld : public PhysicsWorld {
 public:
  OdeWorld(const PhysicsSettings& physics, const GroundSettings& ground);
  ~OdeWorld() override;

  const char* engine_name() const override { return "ode"; }
  dWorldID world() const { return world_; }
  dSpaceID robot_space() const { return robot_space_; }
  dSpaceID static_space() const { return static_space_; }

  void add_static_box(const StaticBox& box) override;
  std::unique_ptr<RobotBody> add_robot(const model::RobotModel& model, int robot_index,
                                       const Eigen::Isometry3d& root_pose,
                                       const model::JointVector& q) override;
  // Owned storage for geometry data, stable for the world's lifetime.
  GeomInfo* new_geom_info(const GeomInfo& info);

  // Collide, step the solver by settings().step, and keep the contacts for sensors.
  void step() override;
  int static_geom_count() const override { return static_geoms_; }

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

  dWorldID world_ = nullptr;
  dSpaceID robot_space_ = nullptr;
  dSpaceID static_space_ = nullptr;
  dJointGroupID contact_group_ = nullptr;
  std::deque<GeomInfo> infos_;
  std::vector<dJointFeedback> feedback_;  // fixed capacity: pointers stay valid within a step
  std::vector<PendingContact> pending_;   // this step's contacts, joined after all collisions
  std::vector<std::pair<dBodyID, LawBodyLoad>> points_per_body_;  // the law's split
  int static_geoms_ = 0;
  SelfContactCandidates self_candidates_;        // rebuilt when the robot geom count changes
  std::unique_ptr<StaticGeomGrid> static_grid_;  // built on the first step, when all are placed
  std::vector<dGeomID> candidates_;
  unsigned long rand_state_ = 0;  // ODE's solver shuffles with a process-wide generator
};

}  // namespace stride::sim
