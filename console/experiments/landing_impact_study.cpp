#include "console/experiments/landing_impact_study.hpp"

#include <array>
#include <cmath>

#include <Eigen/Geometry>

#include "robot/core/error.hpp"
#include "robot/hal/joint_id.hpp"
#include "robot/model/kinematics/jacobians.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/simulation.hpp"
#include "simulator/world/gravity_torque.hpp"

namespace stride::experiments {
namespace {

constexpr std::array<hal::JointId, 6> kLeg = {hal::JointId::LHipYawPitch, hal::JointId::LHipRoll,
                                              hal::JointId::LHipPitch,    hal::JointId::LKneePitch,
                                              hal::JointId::LAnklePitch,  hal::JointId::LAnkleRoll};
constexpr std::array<const char*, 6> kLegNames = {"LHipYawPitch", "LHipRoll",    "LHipPitch",
                                                  "LKneePitch",   "LAnklePitch", "LAnkleRoll"};

// Vertical force the floor pushes the link up with, from the solver's contact forces.
double floor_force_on(const sim::PhysicsWorld& world, int robot, int link) {
  double f = 0;
  for (const sim::ContactRecord& c : world.contacts()) {
    const bool is_a = c.a->robot == robot && c.a->link == link;
    const bool is_b = c.b->robot == robot && c.b->link == link;
    if (is_a == is_b) continue;
    f += is_a ? c.force_on_a.z() : c.force_on_b.z();
  }
  return f;
}

// Motor torques that hold the leg's own weight (the g(theta) of Eq. 6.17), leg order. Joint j
// carries every link of the chain from its own child link down to the foot.
model::LegAngles leg_gravity_compensation(const sim::RobotBody& body) {
  constexpr std::array<const char*, 6> kChildLinks = {"LPelvis", "LHip",   "LThigh",
                                                      "LTibia",  "LAnkle", "LFoot"};
  model::LegAngles g{};
  for (int j = 0; j < 6; ++j)
    for (int k = j; k < 6; ++k)  // the motor opposes gravity
      g[j] -= sim::gravity_torque_about_joint(body, kLegNames[j], {kChildLinks[k]});
  return g;
}

}  // namespace

LandingResult run_landing(const LandingOptions& o) {
  if (!(o.speed > 0 && o.speed < 2)) throw Error("landing: --speed: expected (0, 2) m/s");
  if (!(o.depth >= 0 && o.depth < 0.05)) throw Error("landing: --depth: expected [0, 0.05) m");
  if (!(o.duration > 0.3 && o.duration <= 10))
    throw Error("landing: --seconds: expected (0.3, 10] s");
  sim::Simulation sim(sim::parse_scene_file(o.scene));
  if (sim.robot_count() < 1 || !sim.scene().robots[0].fixed_base)
    throw Error(o.scene + ": expected a robot on a fixed base");
  sim::SimulatedRobot& robot = sim.robot(0);
  if (std::abs(robot.period() - 0.001) > 1e-12)
    throw Error(o.scene + ": the study needs a 1 ms control period (<robot period=\"1ms\">)");
  std::array<int, 6> joint{};
  for (int i = 0; i < 6; ++i) joint[i] = robot.model().joint_index(kLegNames[i]);
  const int foot = robot.model().link_index("LFoot");
  if (foot < 0 || joint[5] < 0) throw Error(o.scene + ": the robot has no NAO left leg");

  // The plan, in the torso frame: the sole keeps its starting pose and sinks at `speed` until it
  // is `depth` below the floor.
  const Eigen::Isometry3d torso = robot.body().link_pose(0);
  model::LegAngles q0{};
  for (int i = 0; i < 6; ++i) q0[i] = robot.body().joint_position(joint[i]);
  const Eigen::Isometry3d start = model::leg_fk(model::Side::Left, q0);
  const double floor_z = -torso.translation().z();  // the floor seen from the torso
  const double end_z = floor_z - o.depth;
  if (start.translation().z() <= floor_z)
    throw Error(o.scene + ": the left sole starts on the floor");

  LandingResult out;
  std::vector<std::pair<double, double>> force;  // time, vertical floor force
  sim.set_controller(0, [&](sim::SimulatedRobot& r) {
    const double t = sim.time();
    force.emplace_back(t, floor_force_on(sim.world(), 0, foot));
    Eigen::Isometry3d desired = start;
    desired.translation().z() = std::max(end_z, start.translation().z() - o.speed * t);
    const double desired_vz = desired.translation().z() > end_z ? -o.speed : 0.0;
    hal::ActuatorFrame cmd = r.latest_commands();
    if (!o.impedance) {
      const model::LegIkResult ik = model::leg_ik(model::Side::Left, desired);
      for (int i = 0; i < 6; ++i) cmd.position[hal::index(kLeg[i])] = ik.q[i];
    } else {
      model::LegAngles q{};
      Eigen::Matrix<double, 6, 1> qd;
      for (int i = 0; i < 6; ++i) {
        q[i] = r.body().joint_position(joint[i]);
        qd[i] = r.body().joint_velocity(joint[i]);
      }
      const Eigen::Isometry3d x = model::leg_fk(model::Side::Left, q);
      const model::Matrix6d j = model::leg_jacobian(model::Side::Left, q);
      const Eigen::Matrix<double, 6, 1> xd = j * qd;  // sole twist [v; omega]
      // Eq. 6.17: tau = J^T (B (x'_d - x') + K (x_d - x)) + g(theta).
      Eigen::Matrix<double, 6, 1> wrench;
      const Eigen::Vector3d v_des(0, 0, desired_vz);
      wrench.head<3>() = o.stiffness.cwiseProduct(desired.translation() - x.translation()) +
                         o.damping.cwiseProduct(v_des - xd.head<3>());
      const Eigen::AngleAxisd rot(desired.linear() * x.linear().transpose());
      wrench.tail<3>() = o.rot_stiffness * rot.angle() * rot.axis() - o.rot_damping * xd.tail<3>();
      const model::LegAngles g = leg_gravity_compensation(r.body());
      const Eigen::Matrix<double, 6, 1> tau = j.transpose() * wrench;
      // HipYawPitch is shared with the right leg: it keeps its position; the other five push.
      for (int i = 1; i < 6; ++i) {
        const int k = hal::index(kLeg[i]);
        cmd.mode[k] = hal::ServoMode::Torque;
        cmd.torque[k] = tau[i] + g[i];
        out.max_torque = std::max(out.max_torque, std::abs(cmd.torque[k]));
      }
    }
    r.write(cmd);
  });
  sim.run_for(o.duration);

  // A rigid contact stops the sole within one step, so a single step's force is an impulse over
  // 1 ms; forces are compared as 10 ms means, the scale a sole's FSRs and filter see (Sec. 6.3).
  bool touching = false;
  double last_sum = 0;
  int last_n = 0;
  for (size_t i = 0; i < force.size(); ++i) {
    const auto [t, f] = force[i];
    if (out.touchdown < 0 && f > 1.0) out.touchdown = t;
    if (out.touchdown >= 0) {
      const double since = t - out.touchdown;
      if (since < 0.01 - 1e-9) out.impulse += f * sim.scene().robots[0].period;
      if (since <= 0.2 && i >= 9) {
        double mean = 0;
        for (size_t k = i - 9; k <= i; ++k) mean += force[k].second / 10;
        if (mean > out.peak_force) out.peak_force = mean, out.peak_at = since;
      }
      if (touching && f < 0.1) ++out.lift_offs;  // the sole came free after carrying load
      if (f > 1.0) touching = true;
      if (f < 0.1) touching = false;
    }
    if (t > o.duration - 0.1) last_sum += f, ++last_n;
  }
  out.trace = std::move(force);
  out.final_force = last_n ? last_sum / last_n : 0;
  return out;
}

}  // namespace stride::experiments
