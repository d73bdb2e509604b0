#include "console/experiments/swing_leg_ode_study.hpp"

#include <cmath>

#include "behaviours/swing_leg/swing_leg_tracking.hpp"
#include "behaviours/swing_leg/thesis_runs.hpp"
#include "console/session/sim_session.hpp"
#include "console/sweep/run_plan.hpp"
#include "robot/core/error.hpp"
#include "robot/hal/joint_id.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::experiments {
namespace {

using Vec5 = swing_leg::Leg5;

// The scene's robot 0 under SwingLegTracking with the options' law and gains.
sim::SceneDescription tracking_scene(const OdeSwingLegOptions& o, const swing_leg::Leg17& gamma) {
  sim::SceneDescription scene = sim::parse_scene_file(o.scene);
  if (scene.robots.empty()) throw Error(o.scene + ": expected a robot");
  sim::RobotPlacement& robot = scene.robots[0];
  robot.has_controller = true;
  ControllerConfig& c = robot.controller;
  c.providers["JointRequest"] = "SwingLegTracking";
  const std::string m = "SwingLegTracking.";
  c.parameters[m + "controller"] = o.controller == swing_leg::Controller::Pd ? "pd" : "adaptive";
  c.parameters[m + "lambda"] = sweep::number_text(o.lambda);
  c.parameters[m + "kd"] = sweep::number_text(o.kd);
  c.parameters[m + "preset"] = o.preset;
  std::string g = "[";
  for (int i = 0; i < gamma.size(); ++i) g += (i ? ", " : "") + sweep::number_text(gamma[i]);
  c.parameters[m + "gamma"] = g + "]";
  return scene;
}

}  // namespace

Eigen::Matrix<double, 17, 1> thesis_ode_gamma() {
  return swing_leg::thesis_ode_gamma();
}

OdeSwingLegResult run_ode_swing_leg(const OdeSwingLegOptions& o) {
  if (!(o.lambda > 0) || !(o.kd > 0)) throw Error("swing-leg ode-track: expected lambda, kd > 0");
  if (!(o.duration > 1 && o.duration <= 600))
    throw Error("swing-leg ode-track: --seconds: expected (1, 600] s");
  if (o.gamma.size() != 0 && (o.gamma.size() != 17 || !(o.gamma.array() > 0).all()))
    throw Error("swing-leg ode-track: expected 17 positive adaptation weights");
  const swing_leg::Leg17 gamma =
      o.gamma.size() ? swing_leg::Leg17(o.gamma) : swing_leg::thesis_ode_gamma();
  console::SimSession session(tracking_scene(o, gamma));
  sim::Simulation& sim = session.simulation();
  const sim::SimulatedRobot& robot = sim.robot(0);
  if (std::abs(robot.period() - 0.001) > 1e-12)
    throw Error(o.scene + ": the study needs a 1 ms control period (<robot period=\"1ms\">)");
  std::array<int, 5> joint{};
  for (int i = 0; i < 5; ++i) {
    const std::string name(hal::kJointNames[hal::index(swing_leg::kLeftLeg3d[i])]);
    joint[i] = robot.model().joint_index(name);
    if (joint[i] < 0) throw Error(o.scene + ": the robot has no joint " + name);
  }
  // The study measures against the simulator's joint angles (ideal sensors); the module sees
  // only what the robot's sensors give it.
  const swing_leg::ReferenceFunction ref = swing_leg::walking_pattern_reference(o.preset);
  Vec5 sum_sq = Vec5::Zero(), worst = Vec5::Zero();
  long frames = 0, counted = 0, saturated = 0;
  OdeSwingLegResult out;
  session.set_frame_observer(0, [&](sim::SimulatedRobot& r) {
    Eigen::VectorXd rq, rqd, rqdd;
    ref(sim.time(), rq, rqd, rqdd);
    if (sim.time() >= 1.0) {  // after the pull-in from the initial posture
      Vec5 err;
      for (int i = 0; i < 5; ++i) err[i] = r.body().joint_position(joint[i]) - rq[i];
      sum_sq += err.cwiseAbs2();
      worst = worst.cwiseMax(err.cwiseAbs());
      ++counted;
    }
    for (int i = 0; i < 5; ++i) {
      const double tau = r.latest_commands().torque[hal::index(swing_leg::kLeftLeg3d[i])];
      if (std::abs(tau) > r.max_joint_torque(joint[i])) ++saturated;
      out.max_torque = std::max(out.max_torque, std::abs(tau));
    }
    ++frames;
  });
  sim.run_for(o.duration);
  out.rms_error = (sum_sq / static_cast<double>(std::max<long>(1, counted))).cwiseSqrt();
  out.max_error = worst;
  out.saturated = static_cast<double>(saturated) / (5.0 * std::max<long>(1, frames));
  return out;
}

}  // namespace stride::experiments
