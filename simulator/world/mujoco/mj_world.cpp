#include "simulator/world/mujoco/mj_world.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include "robot/core/error.hpp"
#include "simulator/scene/scene_limits.hpp"
#include "simulator/world/mujoco/mj_contact_law.hpp"
#include "simulator/world/mujoco/mj_law_friction.hpp"
#include "simulator/world/mujoco/mj_robot_body.hpp"
#include "simulator/world/mujoco/tile_blocks.hpp"

namespace stride::sim {

MjWorld::MjWorld(const PhysicsSettings& physics, const GroundSettings& ground)
    : PhysicsWorld(physics), ground_(ground) {
  static_geoms_ = ground.enabled ? 1 : 0;
}

MjWorld::~MjWorld() {
  if (data_) mj_deleteData(data_);
  if (model_) mj_deleteModel(model_);
}

void MjWorld::add_static_box(const StaticBox& box) {
  boxes_.push_back(box);
  ++static_geoms_;
  dirty_ = true;
}

void MjWorld::add_uneven_patch(const UnevenPatch& patch, std::uint64_t seed) {
  const std::vector<StaticBox> tiles = uneven_tiles(patch, seed);
  for (auto& block : group_tiles(tiles, kTileBlockEdge)) {
    tile_blocks_.push_back(std::move(block));
    block_patch_.push_back(static_cast<int>(patch_friction_.size()));
  }
  patch_friction_.push_back(patch.friction);
  static_geoms_ += static_cast<int>(tiles.size());
  if (!tiles_in_model()) tile_contacts_.set_tiles(physics_, tile_blocks_, block_patch_);
  dirty_ = true;
}

std::unique_ptr<RobotBody> MjWorld::add_robot(const model::RobotModel& model, int robot_index,
                                              const Eigen::Isometry3d& root_pose,
                                              const model::JointVector& q) {
  robots_.push_back({&model, robot_index, root_pose, false});
  initial_q_.push_back(q);
  compile();
  return std::make_unique<MjRobotBody>(*this, model, static_cast<int>(robots_.size()) - 1);
}

void MjWorld::fix_robot(int slot) {
  robots_[slot].fixed = true;
  compile();
}

void MjWorld::compile() {
  const bool in_model = tiles_in_model();
  mjModel* m = load_mjcf(
      in_model ? write_mjcf(physics_, ground_, boxes_, tile_blocks_, robots_, geoms_)
               : write_mjcf(physics_, ground_, boxes_, {}, robots_, geoms_, patch_friction_));
  if (m->ngeom != static_cast<int>(geoms_.size())) {
    mj_deleteModel(m);
    throw Error("mujoco: the compiled scene's geoms do not match the written ones");
  }
  if (data_) mj_deleteData(data_);
  if (model_) mj_deleteModel(model_);
  refreshed_qpos_.clear();
  model_ = m;
  data_ = mj_makeData(model_);
  layouts_.assign(robots_.size(), {});
  for (size_t r = 0; r < robots_.size(); ++r) {
    const model::RobotModel& rm = *robots_[r].model;
    MjRobotLayout& lay = layouts_[r];
    for (size_t l = 0; l < rm.links.size(); ++l)
      lay.body.push_back(
          mj_name2id(model_, mjOBJ_BODY, mjcf_link_name(robots_[r].robot_index, l).c_str()));
    for (size_t j = 0; j < rm.joints.size(); ++j) {
      const int id =
          mj_name2id(model_, mjOBJ_JOINT, mjcf_joint_name(robots_[r].robot_index, j).c_str());
      lay.jnt.push_back(id);
      lay.qpos.push_back(id >= 0 ? model_->jnt_qposadr[id] : -1);
      lay.dof.push_back(id >= 0 ? model_->jnt_dofadr[id] : -1);
      if (id >= 0) data_->qpos[lay.qpos.back()] = initial_q_[r][j];
    }
    // A robot's joints are consecutive (bodies depth first, its free joint first).
    lay.qpos_begin = lay.dof_begin = model_->nq;
    for (int id = 0; id < model_->njnt; ++id) {
      if (std::find(lay.body.begin(), lay.body.end(), model_->jnt_bodyid[id]) == lay.body.end())
        continue;
      const bool free = model_->jnt_type[id] == mjJNT_FREE;
      lay.qpos_begin = std::min(lay.qpos_begin, model_->jnt_qposadr[id]);
      lay.dof_begin = std::min(lay.dof_begin, model_->jnt_dofadr[id]);
      lay.qpos_end = std::max(lay.qpos_end, model_->jnt_qposadr[id] + (free ? 7 : 1));
      lay.dof_end = std::max(lay.dof_end, model_->jnt_dofadr[id] + (free ? 6 : 1));
    }
    if (lay.qpos_end == 0) lay.qpos_begin = lay.dof_begin = 0;
  }
  probes_.clear();
  if (!in_model)
    for (std::size_t k = 0; k < patch_friction_.size(); ++k)
      probes_.push_back(model_->body_geomadr[mj_name2id(
          model_, mjOBJ_BODY, ("tile_probe" + std::to_string(k)).c_str())]);
  motors_.assign(model_->nv, {});
  mj_forward(model_, data_);
  dirty_ = false;
}

void MjWorld::apply_motor(int dof) {
  const MjMotor& mo = motors_[dof];
  model_->dof_frictionloss[dof] = mo.max_torque;
  data_->qfrc_applied[dof] = mo.extra_torque;
}

// A dof's friction-loss row is a velocity constraint bounded by the friction loss, solved with
// the contacts; MuJoCo aims it at zero velocity. Aiming it at the motor's speed within one step,
// as ODE's motor row does, makes it that motor: whatever load the contacts put on the joint, the
// servo holds its speed up to its torque bound.
void MjWorld::retarget_motor_rows() {
  for (int row = 0; row < data_->nefc; ++row)
    if (data_->efc_type[row] == mjCNSTR_FRICTION_DOF)
      data_->efc_aref[row] =
          (motors_[data_->efc_id[row]].speed - data_->efc_vel[row]) / model_->opt.timestep;
}

// mj_step1 as MuJoCo 2.2.2 runs it, with the scene's contact law put into the contacts and their
// rows between collision and the constraint projection.
void MjWorld::step1_with_law() {
  const ContactLaw& law = *physics_.contact_law;
  mj_checkPos(model_, data_);
  mj_checkVel(model_, data_);
  // The last step's refresh already posed every body and geom for these positions: the 1920 tiles
  // of an uneven floor cost a tenth of a step to pose again.
  if (refreshed_qpos_.size() != static_cast<std::size_t>(model_->nq) ||
      !std::equal(refreshed_qpos_.begin(), refreshed_qpos_.end(), data_->qpos)) {
    mj_kinematics(model_, data_);
    mj_comPos(model_, data_);
  }
  mj_camlight(model_, data_);
  mj_tendon(model_, data_);
  mj_crb(model_, data_);
  mj_factorM(model_, data_);
  mj_collision(model_, data_);
  box_contacts_.replace(model_, data_, physics_.max_contacts);
  tile_contacts_.add(model_, data_, probes_, box_contacts_, physics_.max_contacts);
  orient_law_contacts(data_);
  mj_makeConstraint(model_, data_);
  mj_transmission(model_, data_);
  impose_law_rows(model_, data_, law, points_per_body_);
  insert_law_friction_rows(model_, data_, law, physics_.cfm / model_->opt.timestep, friction_rows_);
  mj_projectConstraint(model_, data_);
  mj_sensorPos(model_, data_);
  mj_energyPos(model_, data_);
  mj_fwdVelocity(model_, data_);
  mj_sensorVel(model_, data_);
  mj_energyVel(model_, data_);
}

// mj_step2 as MuJoCo 2.2.2 runs it (Euler), solving twice as ODE's exact solver does: without the
// friction, then with each friction row bounded by mu times the normal force found.
void MjWorld::step2_with_law() {
  mj_fwdActuation(model_, data_);
  mj_fwdAcceleration(model_, data_);
  mj_fwdConstraint(model_, data_);
  if (bound_law_friction(data_, friction_rows_)) mj_fwdConstraint(model_, data_);
  mj_sensorAcc(model_, data_);
  mj_checkAcc(model_, data_);
  mj_Euler(model_, data_);
}

void MjWorld::step() {
  if (dirty_) compile();
  const double before = data_->time;
  if (physics_.contact_law) {
    step1_with_law();
    retarget_motor_rows();
    step2_with_law();
  } else {
    mj_step1(model_, data_);
    retarget_motor_rows();
    mj_step2(model_, data_);
  }
  if (!(data_->time > before)) data_->warning[mjWARN_BADQACC].number += 1;  // it reset itself
  for (int w : {mjWARN_BADQACC, mjWARN_BADQVEL, mjWARN_BADQPOS})
    if (data_->warning[w].number > 0) {
      std::ostringstream msg;
      msg << "physics diverged at t=" << data_->time
          << " s: mujoco found a non-finite state and would reset it (try a smaller step)";
      throw Error(msg.str());
    }
  for (int w : {mjWARN_CONTACTFULL, mjWARN_CNSTRFULL})
    if (data_->warning[w].number > 0)
      throw Error("physics: more contacts or constraints in one step than mujoco has room for (" +
                  std::to_string(model_->nconmax) + " contacts, " + std::to_string(model_->njmax) +
                  " rows; bodies piled into each other or a far too fine floor)");
  // mj_step leaves positions and velocities one step ahead of the derived quantities; bring
  // link poses and velocities up to date for sensors (contacts and their forces stay those of
  // the step just taken).
  mj_kinematics(model_, data_);
  mj_comPos(model_, data_);
  mj_comVel(model_, data_);
  refreshed_qpos_.assign(data_->qpos, data_->qpos + model_->nq);
  mju_zero(data_->xfrc_applied, 6 * model_->nbody);
  for (int v = 0; v < model_->nv; ++v)
    if (motors_[v].extra_torque != 0) {
      motors_[v].extra_torque = 0;
      apply_motor(v);
    }
  record_contacts();
}

void MjWorld::record_contacts() {
  contacts_.clear();
  for (int i = 0; i < data_->ncon && contacts_.size() < scene_limits::kMaxContacts; ++i) {
    const mjContact& c = data_->contact[i];
    if (c.efc_address < 0) continue;  // excluded or beyond the margin: no force
    mjtNum local[6] = {0, 0, 0, 0, 0, 0};
    if (physics_.contact_law)
      law_contact_force(data_, friction_rows_, i, local);
    else
      mj_contactForce(model_, data_, i, local);
    // Contact frame rows: normal (from geom1 to geom2), then two tangents; the force acts on
    // geom2 and its opposite on geom1.
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    for (int row = 0; row < 3; ++row)
      for (int k = 0; k < 3; ++k) f[k] += c.frame[3 * row + k] * local[row];
    ContactRecord rec;
    rec.a = &geoms_[c.geom1];
    rec.b = &geoms_[c.geom2];
    rec.position = Eigen::Vector3d(c.pos[0], c.pos[1], c.pos[2]);
    rec.force_on_a = -f;
    rec.force_on_b = f;
    contacts_.push_back(rec);
  }
}

}  // namespace stride::sim
