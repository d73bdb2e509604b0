#pragma once
// The MuJoCo world: the scene's static geoms and robots compiled into one mjModel (MJCF written
// from our own parsed data, loaded through MuJoCo's virtual file system), stepped by
// mj_step1/mj_step2 with the motors' rows retargeted in between. Adding a robot recompiles; every
// robot then starts again from its initial configuration, which only happens while a scene is being
// built.
#include <memory>
#include <vector>

#include <mujoco/mujoco.h>

#include "simulator/world/contact_law.hpp"
#include "simulator/world/mujoco/mj_box_contacts.hpp"
#include "simulator/world/mujoco/mj_law_friction.hpp"
#include "simulator/world/mujoco/mj_tile_contacts.hpp"
#include "simulator/world/mujoco/mjcf_writer.hpp"
#include "simulator/world/physics_world.hpp"

namespace stride::sim {

// Where one robot's links and joints sit in the compiled model.
struct MjRobotLayout {
  std::vector<int> body;             // mjModel body id per model link
  std::vector<int> qpos, dof, jnt;   // per model joint; -1 for a fixed joint
  int qpos_begin = 0, qpos_end = 0;  // the robot's slice of qpos
  int dof_begin = 0, dof_end = 0;    // and of qvel
};

// A velocity motor on one dof: ODE's motor row, a velocity constraint toward `speed` whose torque
// is bounded by `max_torque`, realised as the dof's friction-loss row retargeted to that speed
// (MjWorld::step).
struct MjMotor {
  double speed = 0, max_torque = 0;
  double extra_torque = 0;  // direct joint torque, cleared after each step
};

class MjWorld : public PhysicsWorld {
 public:
  MjWorld(const PhysicsSettings& physics, const GroundSettings& ground);
  ~MjWorld() override;

  const char* engine_name() const override { return "mujoco"; }
  void add_static_box(const StaticBox& box) override;
  // The tiles in static bodies of nearby tiles (tile_blocks.hpp), not as world geoms; under a
  // contact law outside the model altogether (mj_tile_contacts.hpp).
  void add_uneven_patch(const UnevenPatch& patch, std::uint64_t seed) override;
  // Under a contact law, keeps the tiles in the model as without one: the reference the tile
  // contacts are tested and timed against. Before any patch is added.
  void hold_tiles_in_model() { tiles_in_model_ = true; }
  bool tiles_in_model() const { return tiles_in_model_ || !physics_.contact_law; }
  std::unique_ptr<RobotBody> add_robot(const model::RobotModel& model, int robot_index,
                                       const Eigen::Isometry3d& root_pose,
                                       const model::JointVector& q) override;
  void step() override;
  int static_geom_count() const override { return static_geoms_; }

  void fix_robot(int slot);
  const mjModel* model() const { return model_; }
  mjModel* model() { return model_; }
  mjData* data() const { return data_; }
  const MjRobotLayout& layout(int slot) const { return layouts_[slot]; }
  MjMotor& motor(int dof) { return motors_[dof]; }
  const MjMotor& motor(int dof) const { return motors_[dof]; }
  // Writes the dof's friction-loss bound and qfrc_applied for `dof` from its motor.
  void apply_motor(int dof);

 private:
  void compile();
  void record_contacts();
  void retarget_motor_rows();
  void step1_with_law();
  void step2_with_law();

  GroundSettings ground_;
  std::vector<StaticBox> boxes_;
  std::vector<std::vector<StaticBox>> tile_blocks_;  // uneven floors' tiles, block by block
  std::vector<MjcfRobot> robots_;
  std::vector<model::JointVector> initial_q_;
  std::vector<MjRobotLayout> layouts_;
  std::vector<GeomInfo> geoms_;               // by mjModel geom id
  std::vector<MjMotor> motors_;               // by dof
  std::vector<LawBodyLoad> points_per_body_;  // the contact law's split, by mjModel body id
  LawFrictionRows friction_rows_;             // the contact law's friction rows this step
  OdeBoxBoxContacts box_contacts_;            // the contact law's box-box contacts, ODE's
  MjTileContacts tile_contacts_;              // the law's contacts with tiles out of the model
  std::vector<int> block_patch_;              // each tile block's patch
  std::vector<double> patch_friction_;        // each patch's friction, for its probe geom
  std::vector<int> probes_;                   // each patch's probe geom (tiles out of the model)
  bool tiles_in_model_ = false;
  std::vector<mjtNum> refreshed_qpos_;  // the positions the last step's refresh posed bodies at
  int static_geoms_ = 0;
  bool dirty_ = true;
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
};

}  // namespace stride::sim
