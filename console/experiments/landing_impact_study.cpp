#include "console/experiments/landing_impact_study.hpp"

#include <array>
#include <cmath>

#include "console/session/sim_session.hpp"
#include "console/sweep/run_plan.hpp"
#include "robot/core/error.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "simulator/landing_metrics.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::experiments {
namespace {

constexpr std::array<const char*, 6> kLegNames = {"LHipYawPitch", "LHipRoll",    "LHipPitch",
                                                  "LKneePitch",   "LAnklePitch", "LAnkleRoll"};

std::string vector_text(const Eigen::Vector3d& v) {
  return "[" + sweep::number_text(v.x()) + ", " + sweep::number_text(v.y()) + ", " +
         sweep::number_text(v.z()) + "]";
}

// Robot 0 under LandingPosition or LandingImpedance with the options' plan and gains; the plan's
// descent ends `depth` below the floor, which the module cannot see, so it is worked out here
// from the scene's starting pose.
sim::SceneDescription landing_scene(const LandingOptions& o) {
  sim::SceneDescription scene = sim::parse_scene_file(o.scene);
  if (scene.robots.empty() || !scene.robots[0].fixed_base)
    throw Error(o.scene + ": expected a robot on a fixed base");
  sim::Simulation probe(scene);
  const sim::SimulatedRobot& robot = probe.robot(0);
  if (std::abs(robot.period() - 0.001) > 1e-12)
    throw Error(o.scene + ": the study needs a 1 ms control period (<robot period=\"1ms\">)");
  model::LegAngles q0{};
  for (int i = 0; i < 6; ++i) {
    const int j = robot.model().joint_index(kLegNames[i]);
    if (j < 0 || robot.model().link_index("LFoot") < 0)
      throw Error(o.scene + ": the robot has no NAO left leg");
    q0[i] = robot.body().joint_position(j);
  }
  const double start_z = model::leg_fk(model::Side::Left, q0).translation().z();
  const double floor_z = -robot.body().link_pose(0).translation().z();  // seen from the torso
  if (start_z <= floor_z) throw Error(o.scene + ": the left sole starts on the floor");

  sim::RobotPlacement& placement = scene.robots[0];
  placement.has_controller = true;
  ControllerConfig& c = placement.controller;
  const std::string m = o.impedance ? "LandingImpedance" : "LandingPosition";
  c.providers["JointRequest"] = m;
  c.parameters[m + ".speed"] = sweep::number_text(o.speed);
  c.parameters[m + ".descent"] = sweep::number_text(start_z - (floor_z - o.depth));
  if (o.impedance) {
    c.parameters[m + ".stiffness"] = vector_text(o.stiffness);
    c.parameters[m + ".damping"] = vector_text(o.damping);
    c.parameters[m + ".rot_stiffness"] = sweep::number_text(o.rot_stiffness);
    c.parameters[m + ".rot_damping"] = sweep::number_text(o.rot_damping);
  }
  return scene;
}

}  // namespace

LandingResult run_landing(const LandingOptions& o) {
  if (!(o.speed > 0 && o.speed < 2)) throw Error("landing: --speed: expected (0, 2) m/s");
  if (!(o.depth >= 0 && o.depth < 0.05)) throw Error("landing: --depth: expected [0, 0.05) m");
  if (!(o.duration > 0.3 && o.duration <= 10))
    throw Error("landing: --seconds: expected (0.3, 10] s");
  console::SimSession session(landing_scene(o));
  sim::Simulation& sim = session.simulation();
  const int foot = sim.robot(0).model().link_index("LFoot");
  LandingResult out;
  std::vector<std::pair<double, double>> force;  // time, vertical floor force
  session.set_frame_observer(0, [&](sim::SimulatedRobot& r) {
    force.emplace_back(sim.time(), sim::vertical_floor_force(sim.world(), 0, foot));
    const hal::ActuatorFrame& cmd = r.latest_commands();
    for (int k = 0; k < hal::kNumJoints; ++k)  // the impedance law's torques
      if (cmd.mode[k] == hal::ServoMode::Torque)
        out.max_torque = std::max(out.max_torque, std::abs(cmd.torque[k]));
  });
  sim.run_for(o.duration);
  const sim::LandingTraceSummary l =
      sim::summarize_landing_trace(force, sim.scene().robots[0].period, o.duration);
  out.touchdown = l.touchdown, out.impulse = l.impulse;
  out.peak_force = l.peak_force, out.peak_at = l.peak_at;
  out.lift_offs = l.lift_offs, out.final_force = l.final_force;
  out.trace = std::move(force);
  return out;
}

}  // namespace stride::experiments
