#include "simulator/world/mujoco/mjcf_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sstream>

#include "robot/core/error.hpp"
#include "simulator/world/contact_law.hpp"
#include "simulator/world/mujoco/tile_blocks.hpp"

namespace stride::sim {
namespace {

// MuJoCo's contact by default (PhysicsSettings): its own soft constraints (solref 0.02 1, solimp
// 0.9 0.95 0.001) on an elliptic friction cone, with 10 iterations of its no-slip pass. The
// default pyramidal cone rattles a box on a box and lets a block creep down a ramp it should
// hold; without the no-slip pass a standing NAO creeps 0.11 m in 10 s (tests/simulator: both
// engines' ramp and standing). A scene may state others (mujoco_options.hpp) to measure them.

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string vec(const Eigen::Vector3d& v) {
  return num(v.x()) + " " + num(v.y()) + " " + num(v.z());
}

std::string pose_attrs(const Eigen::Isometry3d& t) {
  const Eigen::Quaterniond q(t.linear());
  return " pos=\"" + vec(t.translation()) + "\" quat=\"" + num(q.w()) + " " + num(q.x()) + " " +
         num(q.y()) + " " + num(q.z()) + "\"";
}

// MuJoCo takes the higher-priority geom's friction: the lower-friction side gets the priority,
// so a pair's friction is the smaller one as in ODE. Robot geoms stand at priority 1.
int static_priority(double friction, double robot_friction) {
  return friction < robot_friction ? 2 : 0;
}

std::string friction_attr(double mu) {
  return " friction=\"" + num(mu) + " 0.005 0.0001\"";
}

std::string shape_attrs(const model::CollisionShape& s) {
  using Kind = model::CollisionShape::Kind;
  switch (s.kind) {
    case Kind::Box:
      return " type=\"box\" size=\"" + vec(s.box_size / 2) + "\"";
    case Kind::Sphere:
      return " type=\"sphere\" size=\"" + num(s.radius) + "\"";
    case Kind::Cylinder:
      return " type=\"cylinder\" size=\"" + num(s.radius) + " " + num(s.length / 2) + "\"";
  }
  return "";
}

// The same mass and inertia floors as the ODE world, so a massless link stays solvable.
std::string inertial(const model::Inertial& in) {
  const double mass = in.mass > 1e-6 ? in.mass : 1e-6;
  Eigen::Matrix3d i = in.inertia;
  if (i.diagonal().minCoeff() <= 0) i = Eigen::Matrix3d::Identity() * 1e-9;
  return "<inertial pos=\"" + vec(in.com) + "\" mass=\"" + num(mass) + "\" fullinertia=\"" +
         num(i(0, 0)) + " " + num(i(1, 1)) + " " + num(i(2, 2)) + " " + num(i(0, 1)) + " " +
         num(i(0, 2)) + " " + num(i(1, 2)) + "\"/>";
}

// The joint's friction-loss row carries its motor (MjWorld::retarget_motor_rows): at MuJoCo's
// largest impedance it is as rigid as ODE's motor row, which reaches its speed within one step.
void write_joint(std::ostream& out, const model::Joint& jt, const std::string& name) {
  using model::JointType;
  if (jt.type == JointType::Fixed) return;
  out << "<joint name=\"" << name << "\" type=\""
      << (jt.type == JointType::Prismatic ? "slide" : "hinge") << "\" axis=\"" << vec(jt.axis)
      << "\" solimpfriction=\"0.9999 0.9999 0.001\"";
  if (jt.type != JointType::Continuous)
    out << " limited=\"true\" range=\"" << num(jt.lower) << " " << num(jt.upper) << "\"";
  out << "/>";
}

void write_link(std::ostream& out, const MjcfRobot& r, int link, const Eigen::Isometry3d& pose,
                std::vector<GeomInfo>& geoms) {
  const model::RobotModel& m = *r.model;
  const model::Link& l = m.links[link];
  out << "<body name=\"" << mjcf_link_name(r.robot_index, link) << "\"" << pose_attrs(pose) << ">";
  if (link == m.root_link && !r.fixed) out << "<freejoint/>";
  if (l.parent_joint >= 0)
    write_joint(out, m.joints[l.parent_joint], mjcf_joint_name(r.robot_index, l.parent_joint));
  out << inertial(l.inertial);
  for (const model::CollisionShape& s : l.collisions) {
    out << "<geom" << shape_attrs(s) << pose_attrs(s.origin) << friction_attr(r.friction)
        << " priority=\"1\"/>";
    geoms.push_back({r.robot_index, link, r.friction});
  }
  for (int j : l.child_joints)
    write_link(out, r, m.joints[j].child_link, m.joints[j].origin, geoms);
  out << "</body>\n";
}

void write_static_box(std::ostream& out, const StaticBox& b, double robot_friction,
                      std::vector<GeomInfo>& geoms) {
  out << "<geom type=\"box\" size=\"" << vec(b.size / 2) << "\"" << pose_attrs(b.pose)
      << friction_attr(b.friction) << " priority=\"" << static_priority(b.friction, robot_friction)
      << "\"/>\n";
  geoms.push_back({-1, -1, b.friction});
}

// Each block a static body at the origin (its geoms' poses are the tiles' own, bit for bit),
// after the robots so their body and geom ids stay as without tiles. Blocks never touch each
// other, so every pair of them is excluded before its geom pairs would be looked at; this closes
// <worldbody>.
void write_tile_blocks(std::ostream& out, const std::vector<std::vector<StaticBox>>& blocks,
                       double robot_friction, std::vector<GeomInfo>& geoms) {
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    out << "<body name=\"" << mjcf_tile_block_name(k) << "\">\n";
    for (const StaticBox& b : blocks[k]) write_static_box(out, b, robot_friction, geoms);
    out << "</body>\n";
  }
  out << "</worldbody>\n";
  if (blocks.size() < 2) return;
  out << "<contact>\n";
  for (std::size_t i = 0; i < blocks.size(); ++i)
    for (std::size_t j = i + 1; j < blocks.size(); ++j)
      out << "<exclude body1=\"" << mjcf_tile_block_name(i) << "\" body2=\""
          << mjcf_tile_block_name(j) << "\"/>\n";
  out << "</contact>\n";
}

}  // namespace

mjModel* load_mjcf(const std::string& xml) {
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "stride_scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(xml.size())) != 0)
    throw Error("mujoco: cannot hold the scene in its virtual file system");
  const int k = mj_findFileVFS(vfs.get(), name);
  std::memcpy(vfs->filedata[k], xml.data(), xml.size());
  char err[1000] = "";
  mjModel* m = mj_loadXML(name, vfs.get(), err, sizeof err);
  mj_deleteVFS(vfs.get());
  if (!m) throw Error(std::string("mujoco: the scene does not compile: ") + err);
  return m;
}

std::string mjcf_link_name(int r, int l) {
  return "r" + std::to_string(r) + "_l" + std::to_string(l);
}

std::string mjcf_joint_name(int r, int j) {
  return "r" + std::to_string(r) + "_j" + std::to_string(j);
}

std::string write_mjcf(const PhysicsSettings& physics, const GroundSettings& ground,
                       const std::vector<StaticBox>& boxes,
                       const std::vector<std::vector<StaticBox>>& tile_blocks,
                       const std::vector<MjcfRobot>& robots, std::vector<GeomInfo>& geoms,
                       const std::vector<double>& tile_probes) {
  geoms.clear();
  const double robot_friction = robot_geom_friction(physics);
  std::ostringstream out;
  using Solver = PhysicsSettings::Solver;
  const bool converged = physics.solver != Solver::Iterative;  // Newton and CG run to convergence
  const char* solver = physics.solver == Solver::Exact ? "Newton"
                       : physics.solver == Solver::Cg  ? "CG"
                                                       : "PGS";
  const bool elliptic = physics.contact_law
                            ? physics.contact_law->cone == ContactLaw::Cone::Elliptic
                            : physics.cone == PhysicsSettings::Cone::Elliptic;
  out << "<mujoco model=\"stride\">\n<compiler angle=\"radian\" balanceinertia=\"true\"/>\n"
      << "<option timestep=\"" << num(physics.step) << "\" gravity=\"" << vec(physics.gravity)
      << "\" integrator=\"Euler\" jacobian=\"dense\" cone=\""
      << (elliptic ? "elliptic" : "pyramidal") << "\" noslip_iterations=\""
      << (physics.contact_law ? 0 : physics.noslip_iterations) << "\" solver=\"" << solver
      << "\" iterations=\"" << (converged ? 100 : physics.iterations) << "\" tolerance=\""
      << (converged ? "1e-10" : "0") << "\"/>\n"
      << "<default><geom solref=\"" << num(physics.contact_timeconst) << " "
      << num(physics.contact_dampratio) << "\" solimp=\"" << num(physics.contact_dmin) << " "
      << num(physics.contact_dmax) << " 0.001\"/></default>\n"
      << "<size njmax=\"1000\" nconmax=\"250\"/>\n<worldbody>\n";
  if (ground.enabled) {
    out << "<geom type=\"plane\" size=\"0 0 1\"" << friction_attr(ground.friction) << " priority=\""
        << static_priority(ground.friction, robot_friction) << "\"/>\n";
    geoms.push_back({-1, -1, ground.friction});
  }
  for (const StaticBox& b : boxes) write_static_box(out, b, robot_friction, geoms);
  for (MjcfRobot r : robots) {
    r.friction = robot_friction;
    write_link(out, r, r.model->root_link, r.root_pose, geoms);
  }
  for (std::size_t k = 0; k < tile_probes.size(); ++k) {
    out << "<body name=\"tile_probe" << k << "\"><geom type=\"box\" size=\"0.5 0.5 0.5\" "
        << "contype=\"0\" conaffinity=\"0\"" << friction_attr(tile_probes[k]) << "/></body>\n";
    geoms.push_back({-1, -1, tile_probes[k]});
  }
  write_tile_blocks(out, tile_blocks, robot_friction, geoms);
  out << "</mujoco>\n";
  return out.str();
}

}  // namespace stride::sim
