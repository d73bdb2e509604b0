#include "simulator/world/mujoco/mj_robot_body.hpp"

#include <cmath>

#include "robot/core/error.hpp"

namespace stride::sim {
namespace {

Eigen::Vector3d v3(const mjtNum* p) {
  return Eigen::Vector3d(p[0], p[1], p[2]);
}

}  // namespace

MjRobotBody::MjRobotBody(MjWorld& world, const model::RobotModel& model, int slot)
    : RobotBody(model), world_(world), slot_(slot) {}

Eigen::Isometry3d MjRobotBody::link_pose(int link) const {
  const mjData* d = world_.data();
  const int b = body(link);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = v3(d->xpos + 3 * b);
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = d->xmat[9 * b + 3 * i + j];
  t.linear() = m;
  return t;
}

Eigen::Vector3d MjRobotBody::link_com(int link) const {
  return v3(world_.data()->xipos + 3 * body(link));
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> MjRobotBody::frame_velocity(int link) const {
  mjtNum v[6];
  mj_objectVelocity(world_.model(), world_.data(), mjOBJ_XBODY, body(link), v, 0);
  return {v3(v), v3(v + 3)};
}

Eigen::Vector3d MjRobotBody::link_com_velocity(int link) const {
  return point_velocity(link, link_com(link));
}

Eigen::Vector3d MjRobotBody::link_angular_velocity(int link) const {
  return frame_velocity(link).first;
}

Eigen::Vector3d MjRobotBody::point_velocity(int link, const Eigen::Vector3d& p) const {
  const auto [w, v] = frame_velocity(link);
  return v + w.cross(p - v3(world_.data()->xpos + 3 * body(link)));
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> MjRobotBody::queued_load(int link) const {
  const mjtNum* x = world_.data()->xfrc_applied + 6 * body(link);
  return {v3(x), v3(x + 3)};
}

bool MjRobotBody::is_hinge(int j) const {
  const int id = world_.layout(slot_).jnt[j];
  return id >= 0 && world_.model()->jnt_type[id] == mjJNT_HINGE;
}

double MjRobotBody::joint_position(int j) const {
  const int a = world_.layout(slot_).qpos[j];
  return a >= 0 ? world_.data()->qpos[a] : 0.0;
}

double MjRobotBody::joint_velocity(int j) const {
  const int v = dof(j);
  return v >= 0 ? world_.data()->qvel[v] : 0.0;
}

// What the motor's row and the joint's limit rows applied over the last step.
double MjRobotBody::joint_constraint_torque(int j) const {
  const int v = dof(j);
  if (v < 0) return 0;
  const mjModel* m = world_.model();
  const mjData* d = world_.data();
  const int id = world_.layout(slot_).jnt[j];
  double tau = 0;
  for (int row = 0; row < d->nefc; ++row)
    if ((d->efc_type[row] == mjCNSTR_LIMIT_JOINT && d->efc_id[row] == id) ||
        (d->efc_type[row] == mjCNSTR_FRICTION_DOF && d->efc_id[row] == v))
      tau += d->efc_force[row] * d->efc_J[row * m->nv + v];
  return tau;
}

void MjRobotBody::set_motor_speed(int j, double speed) {
  world_.motor(dof(j)).speed = speed;
}

void MjRobotBody::set_motor_softness(int, double) {
  throw Error("mujoco: a compliant (spring) servo has no MuJoCo counterpart");
}

// The bound of the motor's row (MjWorld::retarget_motor_rows); zero leaves the joint free.
void MjRobotBody::set_motor_max_torque(int j, double max_torque) {
  const int v = dof(j);
  world_.motor(v).max_torque = max_torque;
  world_.apply_motor(v);
}

void MjRobotBody::add_joint_torque(int j, double torque) {
  const int v = dof(j);
  world_.motor(v).extra_torque += torque;
  world_.apply_motor(v);
}

void MjRobotBody::add_force(int link, const Eigen::Vector3d& force, const Eigen::Vector3d& at) {
  const Eigen::Vector3d p = link_pose(link) * at;
  const Eigen::Vector3d torque = (p - link_com(link)).cross(force);
  mjtNum* x = world_.data()->xfrc_applied + 6 * body(link);
  for (int k = 0; k < 3; ++k) {
    x[k] += force[k];
    x[3 + k] += torque[k];
  }
}

void MjRobotBody::fix_to_world() {
  world_.fix_robot(slot_);
}

void MjRobotBody::move_rigidly(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                               const Eigen::Matrix3d& turn) {
  const mjModel* m = world_.model();
  mjData* d = world_.data();
  const int root = body(model().root_link);
  const int jnt = m->body_jntadr[root];
  if (m->body_jntnum[root] < 1 || m->jnt_type[jnt] != mjJNT_FREE)
    throw Error("mv: a robot fixed to the world cannot be moved on the mujoco engine");
  const Eigen::Isometry3d pose = link_pose(model().root_link);
  const Eigen::Vector3d p = to + turn * (pose.translation() - from);
  const Eigen::Quaterniond q(turn * pose.linear());
  mjtNum* qpos = d->qpos + m->jnt_qposadr[jnt];
  for (int k = 0; k < 3; ++k) qpos[k] = p[k];
  qpos[3] = q.w();
  qpos[4] = q.x();
  qpos[5] = q.y();
  qpos[6] = q.z();
  const MjRobotLayout& lay = world_.layout(slot_);
  for (int v = lay.dof_begin; v < lay.dof_end; ++v) d->qvel[v] = 0;
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_comVel(m, d);
}

void MjRobotBody::visit_state(const std::function<void(const double*, int)>& f) const {
  const MjRobotLayout& lay = world_.layout(slot_);
  f(world_.data()->qpos + lay.qpos_begin, lay.qpos_end - lay.qpos_begin);
  f(world_.data()->qvel + lay.dof_begin, lay.dof_end - lay.dof_begin);
}

}  // namespace stride::sim
