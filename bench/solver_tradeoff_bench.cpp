// What the solver setting buys: for each setting, the cost of a physics step and how well the
// standing NAO, a hanging leg and the 17 s open-loop walk come out. Prints one table row each.
// Usage: solver_tradeoff_bench [--quick] [iterations:sor ...]
//   --quick skips the walk; settings given replace the built-in list (e.g. 8:1.6).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "console/session/sim_session.hpp"
#include "robot/hal/joint_id.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/simulation.hpp"
#include "simulator/world/gravity_torque.hpp"
#include "simulator/world/ode/ode_robot_body.hpp"

namespace {

using namespace stride;
using sim::PhysicsSettings;

struct Setting {
  const char* label;
  PhysicsSettings::Solver solver;
  int iterations;
  double sor = 1.3;  // ODE's default over-relaxation
};

sim::SceneDescription load(const std::string& rel, const Setting& s) {
  auto scene = sim::parse_scene_file(std::string(STRIDE_SOURCE_DIR) + "/" + rel);
  scene.physics.solver = s.solver;
  scene.physics.iterations = s.iterations;
  scene.physics.sor = s.sor;
  for (auto& r : scene.robots) r.sensors.noise = false;
  return scene;
}

// Largest gap between the two bodies' copies of a hinge anchor: the solver's joint error.
double worst_anchor_gap(const sim::SimulatedRobot& robot) {
  double worst = 0;
  const auto& body = dynamic_cast<const sim::OdeRobotBody&>(robot.body());
  for (size_t j = 0; j < robot.model().joints.size(); ++j) {
    dJointID id = body.joint(static_cast<int>(j));
    if (!id || dJointGetType(id) != dJointTypeHinge) continue;
    dVector3 a, b;
    dJointGetHingeAnchor(id, a);
    dJointGetHingeAnchor2(id, b);
    worst = std::max(worst, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
  }
  return worst;
}

struct Standing {
  double us_per_step, drift_mm, fsr_error_pct, anchor_gap_mm;
};

Standing standing(const Setting& s) {
  sim::Simulation sim(load("scenes/nao_stand.xml", s));
  auto& robot = sim.robot(0);
  sim.run_for(0.5);
  const auto start = robot.torso_pose();
  double gap = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < 9500; ++k) {
    sim.step();
    if (k % 100 == 0) gap = std::max(gap, worst_anchor_gap(robot));
  }
  const double us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() /
      9500;
  const auto end = robot.torso_pose();
  double mass = 0;
  for (const auto& l : robot.model().links) mass += l.inertial.mass;
  double fsr = 0;
  for (double f : robot.latest_sensors().fsr) fsr += f;
  return {us, 1000 * std::hypot(end.x - start.x, end.y - start.y, end.z - start.z),
          100 * (fsr - mass * 9.81) / (mass * 9.81), 1000 * gap};
}

// A fixed-base NAO holds its left leg at hip pitch -0.6: hip current against the static one.
double hanging_current_error_pct(const Setting& s) {
  auto scene = load("scenes/nao_stand.xml", s);
  auto& r = scene.robots[0];
  r.fixed_base = true;
  r.auto_height = false;
  r.xyz = Eigen::Vector3d(0, 0, 0.6);
  r.joints["LHipPitch"] = -0.6;
  r.joints["LKneePitch"] = 0;
  r.joints["LAnklePitch"] = 0;
  sim::Simulation sim(scene);
  auto& robot = sim.robot(0);
  sim.run_for(1.0);
  const double torque = sim::gravity_torque_about_joint(robot.body(), "LHipPitch",
                                                        {"LThigh", "LTibia", "LAnkle", "LFoot"});
  const double expected = std::abs(torque) / (130.85 * 0.0068);  // pitch motor
  const double current = robot.latest_sensors().current[hal::index(hal::JointId::LHipPitch)];
  return 100 * (current - expected) / expected;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::vector<std::string> custom;  // "iterations:sor" pairs from the command line
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick")
      quick = true;
    else
      custom.push_back(a);
  }
  std::vector<Setting> settings = {
      {"iterative 5", PhysicsSettings::Solver::Iterative, 5},
      {"iterative 10", PhysicsSettings::Solver::Iterative, 10},
      {"iterative 20", PhysicsSettings::Solver::Iterative, 20},
      {"iterative 40", PhysicsSettings::Solver::Iterative, 40},
      {"exact", PhysicsSettings::Solver::Exact, 20},
  };
  std::vector<std::string> labels;
  labels.reserve(custom.size());
  if (!custom.empty()) settings.clear();
  for (const std::string& c : custom) {
    const auto colon = c.find(':');
    const int iterations = std::stoi(c.substr(0, colon));
    const double sor = colon == std::string::npos ? 1.3 : std::stod(c.substr(colon + 1));
    labels.push_back("iterative " + std::to_string(iterations) + ", SOR " + c.substr(colon + 1));
    settings.push_back(
        {labels.back().c_str(), PhysicsSettings::Solver::Iterative, iterations, sor});
  }
  std::printf(
      "| solver | us/step standing | real time | standing 10 s: torso drift | FSR sum - mg | joint "
      "anchor gap | hanging hip current vs statics | 17 s open-loop walk |\n|---|---|---|---|---|"
      "---|---|---|\n");
  for (const Setting& s : settings) {
    const Standing st = standing(s);
    const double current = hanging_current_error_pct(s);
    std::string walk = "-";
    if (!quick) {
      console::SimSession w(load("scenes/walking/open_loop_medium.xml", s));
      w.simulation().run_for(17.05);
      const auto m = w.simulation().walk_metrics(0).result();
      char buf[160];
      std::snprintf(buf, sizeof buf, "%d steps, %.2f m true / %.2f m FK, %s", m.steps,
                    m.true_distance, m.fk_distance, m.fell ? "fell" : "upright");
      walk = buf;
    }
    std::printf("| %s | %.1f | %.1fx | %.2f mm | %+.2f %% | %.3f mm | %+.1f %% | %s |\n", s.label,
                st.us_per_step, 1000.0 / st.us_per_step, st.drift_mm, st.fsr_error_pct,
                st.anchor_gap_mm, current, walk.c_str());
    std::fflush(stdout);
  }
}
