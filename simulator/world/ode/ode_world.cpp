#include "simulator/world/ode/ode_world.hpp"

#include <algorithm>
#include <vector>

#include "robot/core/error.hpp"
#include "simulator/scene/scene_limits.hpp"
#include "simulator/world/contact_law.hpp"
#include "simulator/world/ode/ode_context.hpp"
#include "simulator/world/ode/ode_robot_body.hpp"
#include "simulator/world/ode/plane_cull.hpp"

namespace stride::sim {
namespace {
constexpr size_t kMaxRecordedContacts = 4096;

// The law's first friction axis at a contact: world x in the contact plane for its pyramid; for its
// elliptic cone the way the contact slips, so that the pyramid's bound mu f_n acts against the
// slip.
Eigen::Vector3d law_axis(const ContactLaw& law, dBodyID b1, dBodyID b2, const dContactGeom& g) {
  const Eigen::Vector3d n(g.normal[0], g.normal[1], g.normal[2]);
  if (law.cone == ContactLaw::Cone::Pyramid) return law_friction_axis(n);
  dVector3 v1 = {0, 0, 0, 0}, v2 = {0, 0, 0, 0};
  if (b1) dBodyGetPointVel(b1, g.pos[0], g.pos[1], g.pos[2], v1);
  if (b2) dBodyGetPointVel(b2, g.pos[0], g.pos[1], g.pos[2], v2);
  const Eigen::Vector3d v(v1[0] - v2[0], v1[1] - v2[1], v1[2] - v2[2]);
  const Eigen::Vector3d slip = v - v.dot(n) * n;
  return slip.norm() > 1e-6 ? Eigen::Vector3d(slip.normalized()) : law_friction_axis(n);
}

}  // namespace

OdeWorld::OdeWorld(const PhysicsSettings& physics, const GroundSettings& ground)
    : PhysicsWorld(physics) {
  ensure_ode_initialised();
  world_ = dWorldCreate();
  dWorldSetGravity(world_, physics.gravity.x(), physics.gravity.y(), physics.gravity.z());
  dWorldSetERP(world_, physics.erp);
  dWorldSetCFM(world_, physics.cfm);
  dWorldSetQuickStepNumIterations(world_, physics.iterations);
  dWorldSetQuickStepW(world_, physics.sor);
  dWorldSetAutoDisableFlag(world_, 0);
  // A contact law's spring starts at the surfaces, as MuJoCo's does; without one, ODE's 0.5 mm
  // layer.
  dWorldSetContactSurfaceLayer(world_, physics.contact_law ? 0.0 : 0.0005);
  if (const auto& law = physics.contact_law) {  // realised by the per-point ERP/CFM below
    const ContactSoftness point = law_point_softness(*law, 1.0, physics.step);
    physics_.contact_erp = point.erp;
    physics_.contact_cfm = point.cfm;
    physics_.contact_spring_per_body = law->per_body;
  }
  robot_space_ = dHashSpaceCreate(nullptr);
  static_space_ = dHashSpaceCreate(nullptr);
  contact_group_ = dJointGroupCreate(0);
  feedback_.resize(kMaxRecordedContacts);
  rand_state_ = static_cast<unsigned long>(physics.seed);
  if (ground.enabled) {
    dGeomID plane = dCreatePlane(static_space_, 0, 0, 1, 0);
    dGeomSetData(plane, new_geom_info({-1, -1, ground.friction}));
    ++static_geoms_;
  }
}

OdeWorld::~OdeWorld() {
  dJointGroupDestroy(contact_group_);
  dSpaceDestroy(robot_space_);  // spaces destroy their geoms (cleanup mode on by default)
  dSpaceDestroy(static_space_);
  dWorldDestroy(world_);
}

GeomInfo* OdeWorld::new_geom_info(const GeomInfo& info) {
  infos_.push_back(info);
  return &infos_.back();
}

void OdeWorld::add_static_box(const StaticBox& box) {
  dGeomID g = dCreateBox(static_space_, box.size.x(), box.size.y(), box.size.z());
  dGeomSetPosition(g, box.pose.translation().x(), box.pose.translation().y(),
                   box.pose.translation().z());
  dMatrix3 r;
  const Eigen::Matrix3d m = box.pose.linear();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[i * 4 + j] = m(i, j);
    r[i * 4 + 3] = 0;
  }
  dGeomSetRotation(g, r);
  dGeomSetData(g, new_geom_info({-1, -1, box.friction}));
  ++static_geoms_;
}

std::unique_ptr<RobotBody> OdeWorld::add_robot(const model::RobotModel& model, int robot_index,
                                               const Eigen::Isometry3d& root_pose,
                                               const model::JointVector& q) {
  return std::make_unique<OdeRobotBody>(*this, model, robot_index, root_pose, q);
}

void OdeWorld::near_callback(void* data, dGeomID g1, dGeomID g2) {
  static_cast<OdeWorld*>(data)->collide_pair(g1, g2);
}

void OdeWorld::collide_pair(dGeomID g1, dGeomID g2) {
  dBodyID b1 = dGeomGetBody(g1);
  dBodyID b2 = dGeomGetBody(g2);
  if (!b1 && !b2) return;
  if (b1 && b2 && dAreConnectedExcluding(b1, b2, dJointTypeContact)) return;  // adjacent links
  const auto* i1 = static_cast<const GeomInfo*>(dGeomGetData(g1));
  const auto* i2 = static_cast<const GeomInfo*>(dGeomGetData(g2));
  if (above_plane(g1, g2) || above_plane(g2, g1)) return;
  const int max_contacts = std::min(physics_.max_contacts, 64);
  dContactGeom geoms[64];
  const int n = dCollide(g1, g2, max_contacts, geoms, sizeof(dContactGeom));
  for (int k = 0; k < n; ++k) {
    dContact c{};
    c.surface.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
    c.surface.mu = std::min(i1->friction, i2->friction);
    c.surface.soft_erp = physics_.contact_erp;
    c.surface.soft_cfm = physics_.contact_cfm;
    c.geom = geoms[k];
    if (physics_.contact_law) {
      c.surface.mode |= dContactFDir1;
      const Eigen::Vector3d t = law_axis(*physics_.contact_law, b1, b2, c.geom);
      for (int i = 0; i < 3; ++i) c.fdir1[i] = t[i];
    }
    pending_.push_back({c, b1, b2, i1, i2});
  }
}

// Joins the step's contacts in the order they were found. Per body, a body's points against the
// static scene share its spring and damper: the same ERP, the CFM over the point's share (by depth
// under a contact law, 1/n under the old contact_spring_per="body").
void OdeWorld::create_contact_joints() {
  points_per_body_.clear();
  if (pending_.size() > scene_limits::kMaxContacts) {
    const std::size_t n = pending_.size();
    pending_.clear();
    throw Error("physics: " + std::to_string(n) + " contact points in one step (at most " +
                std::to_string(scene_limits::kMaxContacts) +
                "; bodies piled into each other or a far too fine floor)");
  }
  const auto static_side = [](const PendingContact& p) {
    return p.b1 && p.b2 ? nullptr : (p.b1 ? p.b1 : p.b2);
  };
  const auto load_of = [this](dBodyID b) -> LawBodyLoad& {
    auto it = std::find_if(points_per_body_.begin(), points_per_body_.end(),
                           [b](const auto& e) { return e.first == b; });
    return it != points_per_body_.end() ? it->second
                                        : points_per_body_.emplace_back(b, LawBodyLoad{}).second;
  };
  if (physics_.contact_spring_per_body)
    for (const PendingContact& p : pending_)
      if (dBodyID b = static_side(p)) {
        LawBodyLoad& load = load_of(b);
        ++load.points;
        load.depth += std::max<double>(p.contact.geom.depth, 0.0);
      }
  const auto& law = physics_.contact_law;
  for (PendingContact& p : pending_) {
    if (physics_.contact_spring_per_body)
      if (dBodyID b = static_side(p)) {
        const LawBodyLoad& load = load_of(b);
        if (law)
          p.contact.surface.soft_cfm /= law_point_share(*law, p.contact.geom.depth, load);
        else
          p.contact.surface.soft_cfm *= load.points;  // as before the law: bit for bit
      }
    dJointID j = dJointCreateContact(world_, contact_group_, &p.contact);
    dJointAttach(j, p.b1, p.b2);
    if (contacts_.size() < feedback_.size()) {
      ContactRecord rec;
      rec.a = p.i1;
      rec.b = p.i2;
      rec.position =
          Eigen::Vector3d(p.contact.geom.pos[0], p.contact.geom.pos[1], p.contact.geom.pos[2]);
      dJointSetFeedback(j, &feedback_[contacts_.size()]);
      contacts_.push_back(rec);
    }
  }
  pending_.clear();
}

void OdeWorld::collide_with_static() {
  const int moving = dSpaceGetNumGeoms(robot_space_);
  const int fixed = dSpaceGetNumGeoms(static_space_);
  if (moving >= fixed) {  // few static geoms: ODE's pairing is as cheap, and its order is ours
    dSpaceCollide2(reinterpret_cast<dGeomID>(robot_space_),
                   reinterpret_cast<dGeomID>(static_space_), this, &near_callback);
    return;
  }
  // ODE would take each robot geom in list order against every static geom in list order; the
  // grid yields the overlapping ones in that same order.
  if (!static_grid_ || static_grid_->size() != fixed)
    static_grid_ = std::make_unique<StaticGeomGrid>(static_space_);
  for (int i = 0; i < moving; ++i) {
    dGeomID g = dSpaceGetGeom(robot_space_, i);
    dReal box[6];
    dGeomGetAABB(g, box);
    static_grid_->overlapping(box, candidates_);
    for (dGeomID s : candidates_) collide_pair(g, s);
  }
}

void OdeWorld::step() {
  contacts_.clear();
  if (self_candidates_.geom_count() != dSpaceGetNumGeoms(robot_space_))
    self_candidates_.rebuild(robot_space_);
  if (self_candidates_.any_overlap()) dSpaceCollide(robot_space_, this, &near_callback);
  collide_with_static();
  create_contact_joints();
  // Each world keeps its own copy of ODE's generator so worlds and resets do not disturb each
  // other.
  dRandSetSeed(rand_state_);
  if (physics_.solver == PhysicsSettings::Solver::Exact)
    dWorldStep(world_, physics_.step);
  else
    dWorldQuickStep(world_, physics_.step);
  rand_state_ = dRandGetSeed();
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const dJointFeedback& fb = feedback_[k];
    contacts_[k].force_on_a = Eigen::Vector3d(fb.f1[0], fb.f1[1], fb.f1[2]);
    contacts_[k].force_on_b = Eigen::Vector3d(fb.f2[0], fb.f2[1], fb.f2[2]);
  }
  dJointGroupEmpty(contact_group_);
}

}  // namespace stride::sim
