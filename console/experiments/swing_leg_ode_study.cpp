#include "console/experiments/swing_leg_ode_study.hpp"

#include <array>
#include <cmath>

#include "behaviours/swing_leg/adaptive_control.hpp"
#include "behaviours/swing_leg/thesis_runs.hpp"
#include "robot/core/error.hpp"
#include "robot/hal/joint_id.hpp"
#include "robot/model/dynamics/swing_leg_3d.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/simulation.hpp"

namespace stride::experiments {
namespace {

using Vec5 = model::Vector5d;
using Par17 = model::Vector17d;

// The 3-D model's joints [hip roll, hip pitch, knee, ankle pitch, ankle roll] on the left leg.
constexpr std::array<hal::JointId, 5> kLegJoints = {
    hal::JointId::LHipRoll, hal::JointId::LHipPitch, hal::JointId::LKneePitch,
    hal::JointId::LAnklePitch, hal::JointId::LAnkleRoll};
constexpr std::array<const char*, 5> kLegNames = {"LHipRoll", "LHipPitch", "LKneePitch",
                                                  "LAnklePitch", "LAnkleRoll"};

}  // namespace

Par17 thesis_ode_gamma() {
  Par17 g;
  g << 0.002, 0.008, 0.005, 0.001, 0.002, 0.006, 0.001, 0.005, 0.007, 0.003, 0.001, 0.004, 0.005,
      0.005, 0.09, 0.015, 0.06;
  return g;
}

OdeSwingLegResult run_ode_swing_leg(const OdeSwingLegOptions& o) {
  if (!(o.lambda > 0) || !(o.kd > 0)) throw Error("swing-leg ode-track: expected lambda, kd > 0");
  if (!(o.duration > 1 && o.duration <= 600))
    throw Error("swing-leg ode-track: --seconds: expected (1, 600] s");
  if (o.gamma.size() != 0 && (o.gamma.size() != 17 || !(o.gamma.array() > 0).all()))
    throw Error("swing-leg ode-track: expected 17 positive adaptation weights");
  const Par17 gamma = o.gamma.size() ? Par17(o.gamma) : thesis_ode_gamma();
  sim::Simulation sim(sim::parse_scene_file(o.scene));
  if (sim.robot_count() < 1) throw Error(o.scene + ": expected a robot");
  sim::SimulatedRobot& robot = sim.robot(0);
  if (std::abs(robot.period() - 0.001) > 1e-12)
    throw Error(o.scene + ": the study needs a 1 ms control period (<robot period=\"1ms\">)");
  std::array<int, 5> joint{};
  for (int i = 0; i < 5; ++i) {
    joint[i] = robot.model().joint_index(kLegNames[i]);
    if (joint[i] < 0) throw Error(o.scene + ": the robot has no joint " + kLegNames[i]);
  }
  const swing_leg::ReferenceFunction ref = swing_leg::walking_pattern_reference(o.preset);
  Par17 a_hat = Par17::Zero();
  Vec5 sum_sq = Vec5::Zero(), worst = Vec5::Zero();
  long frames = 0, counted = 0, saturated = 0;
  OdeSwingLegResult out;
  const double dt = robot.period();
  sim.set_controller(0, [&](sim::SimulatedRobot& r) {
    // Joint state from the simulator (ideal sensors): the study is about the control law.
    Vec5 q, qd;
    for (int i = 0; i < 5; ++i) {
      q[i] = r.body().joint_position(joint[i]);
      qd[i] = r.body().joint_velocity(joint[i]);
    }
    Eigen::VectorXd rq, rqd, rqdd;
    ref(sim.time(), rq, rqd, rqdd);
    const swing_leg::JointReference<5> target{rq, rqd, rqdd};
    if (sim.time() >= 1.0) {  // after the pull-in from the initial posture
      const Vec5 err = q - target.q;
      sum_sq += err.cwiseAbs2();
      worst = worst.cwiseMax(err.cwiseAbs());
      ++counted;
    }
    Vec5 tau;
    if (o.controller == swing_leg::Controller::Adaptive) {
      const auto st = swing_leg::sliding_terms<5>(q, qd, target, o.lambda);
      const model::Leg3dRegressor y = model::leg3d_regressor(q, qd, st.qd_r, st.qdd_r);
      tau = swing_leg::adaptive_torque<5, 17>(y, a_hat, st, o.kd);    // Eq. 5.1
      a_hat += dt * swing_leg::adaptation_rate<5, 17>(y, st, gamma);  // Eq. 5.6
    } else {
      tau = swing_leg::pd_torque<5>(q, qd, target, o.lambda, o.kd);  // Eq. 5.14
    }
    hal::ActuatorFrame cmd = r.latest_commands();
    for (int i = 0; i < 5; ++i) {
      const int k = hal::index(kLegJoints[i]);
      cmd.mode[k] = hal::ServoMode::Torque;
      cmd.torque[k] = tau[i];
      if (std::abs(tau[i]) > r.max_joint_torque(joint[i])) ++saturated;
    }
    out.max_torque = std::max(out.max_torque, tau.cwiseAbs().maxCoeff());
    ++frames;
    r.write(cmd);
  });
  sim.run_for(o.duration);
  out.rms_error = (sum_sq / static_cast<double>(std::max<long>(1, counted))).cwiseSqrt();
  out.max_error = worst;
  out.saturated = static_cast<double>(saturated) / (5.0 * std::max<long>(1, frames));
  return out;
}

}  // namespace stride::experiments
