#include "console/experiments/push_sweep_study.hpp"

#include <cmath>
#include <numbers>

#include "behaviours/balance/modules/balance_modules.hpp"
#include "behaviours/balance/modules/balance_representations.hpp"
#include "behaviours/balance/modules/balance_strategies.hpp"
#include "console/session/sim_session.hpp"
#include "console/sweep/ordered_jobs.hpp"
#include "console/sweep/run_plan.hpp"
#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "robot/framework/binary.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/stance.hpp"

namespace stride::experiments {
namespace {

std::string strategy_module(const std::string& strategy) {
  const auto module = behaviours::balance_module_of(strategy);
  if (!module)
    throw UsageError("stride push-sweep: --strategy: expected ankle, hip, combined or lqr, got " +
                     quote(strategy));
  return std::string(*module);
}

sim::SceneDescription push_scene(const PushSweepOptions& o) {
  sim::SceneDescription scene = sim::parse_scene_file(o.scene);
  if (o.seed) scene.physics.seed = *o.seed;
  if (scene.robots.empty() || !scene.robots[0].has_controller)
    throw InputError("stride push-sweep: " + o.scene + ": robot 0 needs a <controller>");
  scene.robots[0].controller.providers["JointRequest"] = strategy_module(o.strategy);
  console::add_parameter_overrides(scene, o.parameters, "stride push-sweep: --set");
  return scene;
}

// The prediction from the estimator's CoM state and from the simulator's, right after the push.
void predict(const PushSweepOptions& o, const Runtime& rt, const sim::RobotBody& body,
             PushOutcome& r) {
  const ComState& com = rt.representation<ComState>();
  const balance::ComState estimated{com.x, com.xdot};
  const sim::SagittalState t = sim::sagittal_com_state(body);
  const balance::ComState truth{t.x, t.v};
  r.x_est = estimated.x, r.v_est = estimated.v, r.x_true = truth.x, r.v_true = truth.v;
  const BalanceModel& model = rt.representation<BalanceModel>();
  const behaviours::HipBalanceParameters hip;  // the torques the models assume
  const balance::BalanceParams params = balance_params(model, hip.tau_forward, hip.tau_backward);
  const balance::Classification predicted = balance::classify(params, estimated);
  const balance::Classification predicted_true = balance::classify(params, truth);
  r.predicted = predicted.strategy, r.predicted_true = predicted_true.strategy;
  r.expected_recovery = behaviours::strategy_recovers(o.strategy, predicted);
  r.truth_expects_recovery = behaviours::strategy_recovers(o.strategy, predicted_true);
}

}  // namespace

void check_push_sweep(const PushSweepOptions& o) {
  strategy_module(o.strategy);
  if (!(o.duration > 0)) throw UsageError("stride push-sweep: --duration: expected a time > 0");
  if (!(o.settle >= 0) || !(o.observe > 0) || !(o.estimate_delay >= 0))
    throw UsageError(
        "stride push-sweep: --settle, --observe, --estimate-delay: expected times >= 0, > 0, "
        ">= 0");
  for (double i : o.impulses)
    if (!(i >= 0)) throw UsageError("stride push-sweep: --impulses: expected values >= 0 N*s");
  if (o.impulses.size() * o.directions.size() > kMaxPushes)
    throw UsageError("stride push-sweep: " + std::to_string(o.impulses.size()) + " impulses x " +
                     std::to_string(o.directions.size()) +
                     " directions is more than one sweep runs (at most " +
                     std::to_string(kMaxPushes) + " pushes); narrow the ranges or split the sweep");
}

PushOutcome run_push(const PushSweepOptions& o, double impulse, double direction) {
  sim::SceneDescription scene = push_scene(o);
  const std::string robot = scene.robots[0].name;
  console::SimSession session(std::move(scene));
  auto& sim = session.simulation();
  const sim::RobotBody& body = sim.robot(0).body();

  sim.run_for(o.settle);
  const auto feet_before = sim::foot_positions(body);
  const double a = direction * std::numbers::pi / 180;
  const Eigen::Vector3d force = impulse / o.duration * Eigen::Vector3d(std::cos(a), std::sin(a), 0);
  sim.push(robot, "torso", force, Eigen::Vector3d::Zero(), o.duration);
  sim.run_for(o.duration + o.estimate_delay);

  PushOutcome r;
  r.impulse = impulse;
  r.direction = direction;
  predict(o, *session.runtime(0), body, r);
  for (double t = 0; t < o.observe - 1e-9; t += 0.1) {
    sim.run_for(0.1);
    r.fell = r.fell || sim.robot(0).fallen();
  }
  r.foot_motion = sim::foot_motion(feet_before, sim::foot_positions(body));
  return r;
}

std::vector<PushOutcome> run_push_sweep(const PushSweepOptions& o, int jobs) {
  push_scene(o);  // a scene that cannot be pushed is the caller's error, before any job
  std::vector<std::pair<double, double>> pushes;
  for (double impulse : o.impulses)
    for (double direction : o.directions) pushes.emplace_back(impulse, direction);
  std::vector<PushOutcome> out(pushes.size());
  sweep::run_jobs(
      pushes.size(), jobs,
      [&](std::size_t i) { return to_binary(run_push(o, pushes[i].first, pushes[i].second)); },
      [&](std::size_t i, std::string&& bytes) {
        from_binary(out[i], bytes);
        return true;
      },
      [&](std::size_t i) {
        return o.scene + " (impulse " + sweep::number_text(pushes[i].first) + " N s, direction " +
               sweep::number_text(pushes[i].second) + " deg)";
      });
  return out;
}

}  // namespace stride::experiments
