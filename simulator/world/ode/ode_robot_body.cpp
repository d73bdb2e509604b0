#include "simulator/world/ode/ode_robot_body.hpp"

#include <cmath>

#include "simulator/world/contact_law.hpp"

namespace stride::sim {
namespace {

void set_pose(dBodyID b, const Eigen::Isometry3d& t) {
  dBodySetPosition(b, t.translation().x(), t.translation().y(), t.translation().z());
  const Eigen::Quaterniond q(t.linear());
  const dQuaternion dq = {q.w(), q.x(), q.y(), q.z()};
  dBodySetQuaternion(b, dq);
}

void to_ode_rotation(const Eigen::Matrix3d& m, dMatrix3 r) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[i * 4 + j] = m(i, j);
    r[i * 4 + 3] = 0;
  }
}

dGeomID make_geom(dSpaceID space, const model::CollisionShape& s) {
  using Kind = model::CollisionShape::Kind;
  switch (s.kind) {
    case Kind::Box:
      return dCreateBox(space, s.box_size.x(), s.box_size.y(), s.box_size.z());
    case Kind::Sphere:
      return dCreateSphere(space, s.radius);
    case Kind::Cylinder:
      return dCreateCylinder(space, s.radius, s.length);
  }
  return nullptr;
}

}  // namespace

Eigen::Isometry3d to_isometry(const dReal* pos, const dReal* rot) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(pos[0], pos[1], pos[2]);
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = rot[i * 4 + j];
  t.linear() = m;
  return t;
}

namespace {

// One URDF joint as an ODE joint between `child` and `parent` at its zero-pose `frame`;
// `stops` says whether its limits became hinge stops.
dJointID make_joint(dWorldID world, const model::Joint& jt, dBodyID child, dBodyID parent,
                    const Eigen::Isometry3d& frame, bool& stops) {
  const Eigen::Vector3d axis = frame.linear() * jt.axis;
  const Eigen::Vector3d anchor = frame.translation();
  dJointID id = nullptr;
  switch (jt.type) {
    case model::JointType::Revolute:
    case model::JointType::Continuous:
      id = dJointCreateHinge(world, nullptr);
      dJointAttach(id, child, parent);
      dJointSetHingeAnchor(id, anchor.x(), anchor.y(), anchor.z());
      dJointSetHingeAxis(id, axis.x(), axis.y(), axis.z());
      if (jt.type == model::JointType::Revolute) {
        dJointSetHingeParam(id, dParamLoStop, jt.lower);
        dJointSetHingeParam(id, dParamHiStop, jt.upper);
        stops = true;
      }
      break;
    case model::JointType::Prismatic:
      id = dJointCreateSlider(world, nullptr);
      dJointAttach(id, child, parent);
      dJointSetSliderAxis(id, axis.x(), axis.y(), axis.z());
      dJointSetSliderParam(id, dParamLoStop, jt.lower);
      dJointSetSliderParam(id, dParamHiStop, jt.upper);
      break;
    case model::JointType::Fixed:
      id = dJointCreateFixed(world, nullptr);
      dJointAttach(id, child, parent);
      dJointSetFixed(id);
      break;
  }
  return id;
}

}  // namespace

OdeRobotBody::OdeRobotBody(OdeWorld& world, const model::RobotModel& model, int robot_index,
                           const Eigen::Isometry3d& root_pose, const model::JointVector& q)
    : RobotBody(model), world_(world.world()) {
  const int nl = static_cast<int>(model.links.size());
  const int nj = static_cast<int>(model.joints.size());
  std::vector<Eigen::Isometry3d> zero_poses, poses;
  model::link_poses(model, model::zero_joints(model), zero_poses);
  model::JointVector qm = q;
  model::apply_mimic(model, qm);
  model::link_poses(model, qm, poses);

  bodies_.resize(nl);
  for (int i = 0; i < nl; ++i) {
    const model::Link& l = model.links[i];
    dBodyID b = dBodyCreate(world.world());
    dMass m;
    dMassSetZero(&m);
    // A massless link would make the solver singular; give it a negligible mass instead.
    const double mass = l.inertial.mass > 1e-6 ? l.inertial.mass : 1e-6;
    Eigen::Matrix3d in = l.inertial.inertia;
    if (in.diagonal().minCoeff() <= 0) in = Eigen::Matrix3d::Identity() * 1e-9;
    dMassSetParameters(&m, mass, 0, 0, 0, in(0, 0), in(1, 1), in(2, 2), in(0, 1), in(0, 2),
                       in(1, 2));
    dBodySetMass(b, &m);
    Eigen::Isometry3d body_pose = root_pose * zero_poses[i];
    body_pose.translate(l.inertial.com);
    set_pose(b, body_pose);
    dBodySetData(b, const_cast<model::Link*>(&l));
    for (const auto& s : l.collisions) {
      dGeomID g = make_geom(world.robot_space(), s);
      dGeomSetBody(g, b);
      const Eigen::Vector3d off = s.origin.translation() - l.inertial.com;
      dGeomSetOffsetPosition(g, off.x(), off.y(), off.z());
      dMatrix3 r;
      to_ode_rotation(s.origin.linear(), r);
      dGeomSetOffsetRotation(g, r);
      dGeomSetData(g, world.new_geom_info({robot_index, i, robot_geom_friction(world.settings())}));
    }
    bodies_[i] = b;
  }
  // Joints are created in the zero pose, so ODE's hinge angle reads the URDF joint value.
  joints_.assign(nj, nullptr);
  stops_set_.assign(nj, 0);
  feedback_.resize(nj);
  for (int j = 0; j < nj; ++j) {
    const model::Joint& jt = model.joints[j];
    const Eigen::Isometry3d frame = root_pose * zero_poses[jt.child_link];
    bool stops = false;
    dJointID id = make_joint(world.world(), jt, bodies_[jt.child_link], bodies_[jt.parent_link],
                             frame, stops);
    if (stops) stops_set_[j] = 1;
    dJointSetFeedback(id, &feedback_[j]);
    joints_[j] = id;
  }
  // Now move every body to the requested configuration.
  for (int i = 0; i < nl; ++i) {
    Eigen::Isometry3d body_pose = root_pose * poses[i];
    body_pose.translate(model.links[i].inertial.com);
    set_pose(bodies_[i], body_pose);
  }
}

Eigen::Isometry3d OdeRobotBody::link_pose(int link) const {
  Eigen::Isometry3d t =
      to_isometry(dBodyGetPosition(bodies_[link]), dBodyGetRotation(bodies_[link]));
  t.translate(-model().links[link].inertial.com);
  return t;
}

Eigen::Vector3d OdeRobotBody::link_com(int link) const {
  const dReal* p = dBodyGetPosition(bodies_[link]);
  return Eigen::Vector3d(p[0], p[1], p[2]);
}

double OdeRobotBody::joint_position(int j) const {
  dJointID id = joints_[j];
  switch (dJointGetType(id)) {
    case dJointTypeHinge:
      return dJointGetHingeAngle(id);
    case dJointTypeSlider:
      return dJointGetSliderPosition(id);
    default:
      return 0;
  }
}

void OdeRobotBody::keep_stops_within_reach(int j, double q) {
  // One step moves a joint far less than this (0.2 rad in 1 ms is 200 rad/s).
  constexpr double kReach = 0.2;
  const model::Joint& jt = model().joints[j];
  if (jt.type != model::JointType::Revolute) return;
  const bool near = q < jt.lower + kReach || q > jt.upper - kReach;
  if (near == static_cast<bool>(stops_set_[j])) return;
  dJointID id = joints_[j];
  if (near) {  // the low stop first: ODE refuses a low stop above the high one
    dJointSetHingeParam(id, dParamLoStop, jt.lower);
    dJointSetHingeParam(id, dParamHiStop, jt.upper);
  } else {
    dJointSetHingeParam(id, dParamLoStop, -dInfinity);
    dJointSetHingeParam(id, dParamHiStop, dInfinity);
  }
  stops_set_[j] = near;
}

double OdeRobotBody::joint_velocity(int j) const {
  dJointID id = joints_[j];
  switch (dJointGetType(id)) {
    case dJointTypeHinge:
      return dJointGetHingeAngleRate(id);
    case dJointTypeSlider:
      return dJointGetSliderPositionRate(id);
    default:
      return 0;
  }
}

double OdeRobotBody::joint_constraint_torque(int j) const {
  dJointID id = joints_[j];
  if (dJointGetType(id) != dJointTypeHinge) return 0;
  const dJointFeedback& fb = feedback_[j];
  dVector3 anchor, axis;
  dJointGetHingeAnchor(id, anchor);
  dJointGetHingeAxis(id, axis);
  const dReal* com = dBodyGetPosition(dJointGetBody(id, 0));
  // t1 is about body1's centre of mass; remove the moment of the constraint force at the anchor.
  const Eigen::Vector3d r(anchor[0] - com[0], anchor[1] - com[1], anchor[2] - com[2]);
  const Eigen::Vector3d f(fb.f1[0], fb.f1[1], fb.f1[2]);
  const Eigen::Vector3d t(fb.t1[0], fb.t1[1], fb.t1[2]);
  return (t - r.cross(f)).dot(Eigen::Vector3d(axis[0], axis[1], axis[2]));
}

Eigen::Vector3d OdeRobotBody::link_com_velocity(int link) const {
  const dReal* v = dBodyGetLinearVel(bodies_[link]);
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

Eigen::Vector3d OdeRobotBody::link_angular_velocity(int link) const {
  const dReal* w = dBodyGetAngularVel(bodies_[link]);
  return Eigen::Vector3d(w[0], w[1], w[2]);
}

Eigen::Vector3d OdeRobotBody::point_velocity(int link, const Eigen::Vector3d& p) const {
  dVector3 v;
  dBodyGetPointVel(bodies_[link], p.x(), p.y(), p.z(), v);
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> OdeRobotBody::queued_load(int link) const {
  const dReal* f = dBodyGetForce(bodies_[link]);
  const dReal* t = dBodyGetTorque(bodies_[link]);
  return {Eigen::Vector3d(f[0], f[1], f[2]), Eigen::Vector3d(t[0], t[1], t[2])};
}

bool OdeRobotBody::is_hinge(int j) const {
  return joints_[j] && dJointGetType(joints_[j]) == dJointTypeHinge;
}

void OdeRobotBody::set_motor_speed(int j, double speed) {
  dJointSetHingeParam(joints_[j], dParamVel, speed);
}

void OdeRobotBody::set_motor_softness(int j, double softness) {
  dJointSetHingeParam(joints_[j], dParamCFM, softness);
}

void OdeRobotBody::set_motor_max_torque(int j, double max_torque) {
  dJointSetHingeParam(joints_[j], dParamFMax, max_torque);
}

void OdeRobotBody::add_joint_torque(int j, double torque) {
  dJointAddHingeTorque(joints_[j], torque);
}

void OdeRobotBody::add_force(int link, const Eigen::Vector3d& force, const Eigen::Vector3d& at) {
  const Eigen::Vector3d rel = at - model().links[link].inertial.com;
  dBodyAddForceAtRelPos(bodies_[link], force.x(), force.y(), force.z(), rel.x(), rel.y(), rel.z());
}

void OdeRobotBody::fix_to_world() {
  dJointID weld = dJointCreateFixed(world_, nullptr);
  dJointAttach(weld, bodies_[model().root_link], nullptr);
  dJointSetFixed(weld);
}

void OdeRobotBody::move_rigidly(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                const Eigen::Matrix3d& turn) {
  for (dBodyID b : bodies_) {
    const dReal* p = dBodyGetPosition(b);
    const Eigen::Vector3d moved = to + turn * (Eigen::Vector3d(p[0], p[1], p[2]) - from);
    const Eigen::Matrix3d turned = turn * to_isometry(p, dBodyGetRotation(b)).linear();
    dMatrix3 out;
    to_ode_rotation(turned, out);
    dBodySetPosition(b, moved.x(), moved.y(), moved.z());
    dBodySetRotation(b, out);
    dBodySetLinearVel(b, 0, 0, 0);
    dBodySetAngularVel(b, 0, 0, 0);
  }
}

void OdeRobotBody::visit_state(const std::function<void(const double*, int)>& f) const {
  for (dBodyID b : bodies_) {
    f(dBodyGetPosition(b), 3);
    f(dBodyGetQuaternion(b), 4);
    f(dBodyGetLinearVel(b), 3);
    f(dBodyGetAngularVel(b), 3);
  }
}

}  // namespace stride::sim
