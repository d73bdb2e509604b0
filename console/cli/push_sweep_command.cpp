// `stride push-sweep --scene S --strategy ankle|hip|combined|lqr --impulses a:b:step
//  --directions d1,d2 [--duration s] [--settle s] [--observe s] [--estimate-delay s] [--seed N]
//  [--set "Module.field=value ..."] [--csv f] [--json]`:
// pushes the standing robot's torso once per (impulse, direction) in a freshly loaded scene,
// predicts the outcome from the post-push CoM state with balance::classify (thesis Ch. 7) and
// compares it with what the simulation does in the next seconds.
// The Ch. 7 models are sagittal: the CoM state along x is classified, so directions other than
// 0 (forward) and 180 (backward) add lateral motion the prediction does not see.
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <numbers>
#include <optional>
#include <ostream>
#include <sstream>

#include "behaviours/balance/modules/balance_modules.hpp"
#include "behaviours/balance/modules/balance_representations.hpp"
#include "behaviours/balance/strategy_classifier.hpp"
#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/output/output_paths.hpp"
#include "console/session/sim_session.hpp"
#include "robot/core/error.hpp"
#include "robot/core/json_writer.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/output_file.hpp"
#include "robot/core/quote.hpp"
#include "robot/runtime/parameter_override.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::cli {

namespace {

struct SweepOptions {
  std::string scene;
  std::string strategy = "ankle";
  std::vector<double> impulses, directions;
  double duration = 0.05, settle = 1.5, observe = 3.0;
  // The filter needs a few frames to follow the jump in velocity; the classes are invariant
  // along saturated trajectories, so classifying a little after the push is consistent.
  double estimate_delay = 0.03;
  std::optional<std::uint64_t> seed;
  std::vector<ParameterOverride> parameters;  // --set "Module.field=value ..."
};

std::vector<ParameterOverride> parse_settings(const std::string& text) {
  std::vector<ParameterOverride> out;
  std::istringstream ss(text);
  for (std::string item; ss >> item;) {
    try {
      out.push_back(parse_parameter_override(item, "stride push-sweep: --set"));
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
  }
  return out;
}

// One sweep's pushes at most: each is a few simulated seconds, so 2000 take an hour or more.
constexpr std::size_t kMaxPushes = 2000;

// Feet moving more than this means the robot stepped or slid: not a recovery in place.
constexpr double kMaxFootMotion = 0.02;

struct PushResult {
  double impulse = 0, direction = 0;
  balance::ComState estimated, truth;  // along the sagittal axis x, ground frame
  balance::Classification predicted, predicted_truth;
  bool expected_recovery = false;  // the chosen strategy's region contains the estimate
  bool fell = false;
  double foot_motion = 0;
  bool truth_expects_recovery = false;  // the same from the simulator's CoM state
  bool recovered() const { return !fell && foot_motion <= kMaxFootMotion; }
  bool agree() const { return expected_recovery == recovered(); }
};

std::string module_of(const std::string& strategy) {
  if (strategy == "ankle") return "AnkleBalance";
  if (strategy == "hip") return "HipBalance";
  if (strategy == "combined") return "CombinedBalance";
  if (strategy == "lqr") return "LqrBalance";
  throw UsageError("stride push-sweep: --strategy: expected ankle, hip, combined or lqr, got " +
                   quote(strategy));
}

bool strategy_recovers(const std::string& strategy, const balance::Classification& c) {
  if (strategy == "ankle") return c.ankle_recovers;
  if (strategy == "hip") return c.hip_recovers;
  return c.combined_recovers;  // combined and LQR use ankle and hip together
}

double parse_value(const std::string& flag, const std::string& s) {
  try {
    return parse_number(s, "stride push-sweep: " + flag);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

// "a:b:step" (inclusive) or "v1,v2,...".
std::vector<double> parse_list(const std::string& flag, const std::string& text) {
  std::vector<std::string> parts;
  const char sep = text.find(':') != std::string::npos ? ':' : ',';
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, sep);) parts.push_back(p);
  std::vector<double> v;
  if (sep == ',') {
    for (const auto& p : parts) v.push_back(parse_value(flag, p));
  } else {
    if (parts.size() != 3)
      throw UsageError("stride push-sweep: " + flag + ": expected first:last:step, got " +
                       quote(text));
    const double a = parse_value(flag, parts[0]), b = parse_value(flag, parts[1]),
                 s = parse_value(flag, parts[2]);
    if (!(s > 0) || b < a)
      throw UsageError("stride push-sweep: " + flag + ": expected first <= last and step > 0");
    if ((b - a) / s >= kMaxPushes)
      throw UsageError("stride push-sweep: " + flag + ": " + quote(text) + " has more than " +
                       std::to_string(kMaxPushes) + " values; expected a coarser step");
    for (int i = 0; a + i * s <= b + 1e-9 * s; ++i) v.push_back(a + i * s);
  }
  if (v.empty()) throw UsageError("stride push-sweep: " + flag + ": expected at least one value");
  return v;
}

std::array<Eigen::Vector2d, 2> foot_positions(const sim::RobotBody& body) {
  const auto& m = body.model();
  return {body.link_pose(m.link_index("LFoot")).translation().head<2>(),
          body.link_pose(m.link_index("RFoot")).translation().head<2>()};
}

PushResult run_push(const SweepOptions& o, double impulse, double direction) {
  sim::SceneDescription scene = sim::parse_scene_file(o.scene);
  if (o.seed) scene.physics.seed = *o.seed;
  if (scene.robots.empty() || !scene.robots[0].has_controller)
    throw InputError("stride push-sweep: " + o.scene + ": robot 0 needs a <controller>");
  auto& controller = scene.robots[0].controller;
  controller.providers["JointRequest"] = module_of(o.strategy);
  console::add_parameter_overrides(scene, o.parameters, "stride push-sweep: --set");
  const std::string robot = scene.robots[0].name;
  console::SimSession session(std::move(scene));
  auto& sim = session.simulation();
  const Runtime& rt = *session.runtime(0);
  const sim::RobotBody& body = sim.robot(0).body();

  sim.run_for(o.settle);
  const auto feet_before = foot_positions(body);
  const double a = direction * std::numbers::pi / 180;
  const Eigen::Vector3d force = impulse / o.duration * Eigen::Vector3d(std::cos(a), std::sin(a), 0);
  sim.push(robot, "torso", force, Eigen::Vector3d::Zero(), o.duration);
  sim.run_for(o.duration + o.estimate_delay);

  PushResult r;
  r.impulse = impulse;
  r.direction = direction;
  const ComState& com = rt.representation<ComState>();
  r.estimated = {com.x, com.xdot};
  const Eigen::Vector3d p = body.centre_of_mass(), v = body.centre_of_mass_velocity();
  const auto feet = foot_positions(body);
  r.truth = {p.x() - 0.5 * (feet[0].x() + feet[1].x()), v.x()};  // ground frame: ankles' midpoint
  const BalanceModel& model = rt.representation<BalanceModel>();
  const behaviours::HipBalanceParameters hip;  // the torques the models assume
  const balance::BalanceParams params = balance_params(model, hip.tau_forward, hip.tau_backward);
  r.predicted = balance::classify(params, r.estimated);
  r.predicted_truth = balance::classify(params, r.truth);
  r.expected_recovery = strategy_recovers(o.strategy, r.predicted);
  r.truth_expects_recovery = strategy_recovers(o.strategy, r.predicted_truth);

  for (double t = 0; t < o.observe - 1e-9; t += 0.1) {
    sim.run_for(0.1);
    r.fell = r.fell || sim.robot(0).fallen();
  }
  const auto feet_after = foot_positions(body);
  for (int i = 0; i < 2; ++i)
    r.foot_motion = std::max(r.foot_motion, (feet_after[i] - feet_before[i]).norm());
  return r;
}

std::string observed(const PushResult& r) {
  return r.recovered() ? "recovered" : r.fell ? "fell" : "stepped";
}

void print_table(std::ostream& out, const SweepOptions& o, const std::vector<PushResult>& rs) {
  out << "push sweep: strategy " << o.strategy << ", push " << o.duration << " s on the torso\n";
  out << std::setw(8) << "impulse" << std::setw(5) << "dir" << std::setw(9) << "x_est"
      << std::setw(9) << "v_est" << std::setw(9) << "x_true" << std::setw(9) << "v_true"
      << std::setw(10) << "predicted" << std::setw(10) << "pred_true" << std::setw(10) << "expected"
      << std::setw(11) << "observed" << std::setw(7) << "agree"
      << "\n";
  int agree = 0, agree_truth = 0;
  for (const auto& r : rs) {
    agree += r.agree();
    agree_truth += r.truth_expects_recovery == r.recovered();
    out << std::fixed << std::setprecision(2) << std::setw(8) << r.impulse << std::setw(5)
        << std::setprecision(0) << r.direction << std::setprecision(4) << std::setw(9)
        << r.estimated.x << std::setw(9) << r.estimated.v << std::setw(9) << r.truth.x
        << std::setw(9) << r.truth.v << std::setw(10) << balance::to_string(r.predicted.strategy)
        << std::setw(10) << balance::to_string(r.predicted_truth.strategy) << std::setw(10)
        << (r.expected_recovery ? "recover" : "fall") << std::setw(11) << observed(r)
        << std::setw(7) << (r.agree() ? "yes" : "no") << "\n";
  }
  out << std::defaultfloat << "agreement: " << agree << "/" << rs.size() << " = "
      << std::setprecision(3) << 100.0 * agree / rs.size() << " %\n";
  out << "agreement from the simulator's CoM state: " << agree_truth << "/" << rs.size() << " = "
      << 100.0 * agree_truth / rs.size() << " %\n";
}

void write_csv(std::ostream& f, const std::vector<PushResult>& rs) {
  f << "impulse,direction,x_est,v_est,x_true,v_true,predicted,predicted_true,expected,observed,"
       "foot_motion,agree\n";
  for (const auto& r : rs)
    f << r.impulse << ',' << r.direction << ',' << r.estimated.x << ',' << r.estimated.v << ','
      << r.truth.x << ',' << r.truth.v << ',' << balance::to_string(r.predicted.strategy) << ','
      << balance::to_string(r.predicted_truth.strategy) << ','
      << (r.expected_recovery ? "recover" : "fall") << ',' << observed(r) << ',' << r.foot_motion
      << ',' << r.agree() << '\n';
}

void write_json(std::ostream& out, const SweepOptions& o, const std::vector<PushResult>& rs) {
  int agree = 0;
  JsonWriter j(JsonWriter::Style::Spaced);
  j.begin_object().field("strategy", o.strategy).key("pushes").begin_array();
  for (const PushResult& r : rs) {
    agree += r.agree();
    j.begin_object().field("impulse", r.impulse).field("direction", r.direction);
    j.field("x_est", r.estimated.x).field("v_est", r.estimated.v);
    j.field("x_true", r.truth.x).field("v_true", r.truth.v);
    j.field("predicted", balance::to_string(r.predicted.strategy));
    j.field("expected", r.expected_recovery ? "recover" : "fall").field("observed", observed(r));
    j.field("foot_motion", r.foot_motion).field("agree", r.agree()).end_object();
  }
  j.end_array().field("agreement", static_cast<double>(agree) / rs.size()).end_object();
  out << j.str() << "\n";
}

}  // namespace

int push_sweep_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "push-sweep");
    if (asks_for_settings(args)) {
      print_module_parameters(out);
      return kExitOk;
    }
    SweepOptions o;
    o.scene = a.text("--scene");
    o.strategy = a.text_or("--strategy", "ankle");
    module_of(o.strategy);
    o.impulses = parse_list("--impulses", a.text("--impulses"));
    o.directions = parse_list("--directions", a.text_or("--directions", "0,180"));
    o.duration = a.number_or("--duration", o.duration);
    o.settle = a.number_or("--settle", o.settle);
    o.observe = a.number_or("--observe", o.observe);
    o.estimate_delay = a.number_or("--estimate-delay", o.estimate_delay);
    o.parameters = parse_settings(a.text_or("--set", ""));
    if (a.has("--seed")) o.seed = a.unsigned_integer("--seed");
    const std::string csv = a.text_or("--csv", "");
    const bool json = a.flag("--json");
    a.finish();
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
                       std::to_string(kMaxPushes) +
                       " pushes); narrow the ranges or split the sweep");
    if (!csv.empty()) console::check_output_file("stride push-sweep: --csv", csv);

    std::vector<PushResult> results;
    for (double impulse : o.impulses)
      for (double direction : o.directions) results.push_back(run_push(o, impulse, direction));
    if (json)
      write_json(out, o, results);
    else
      print_table(out, o, results);
    if (!csv.empty()) {
      std::ostringstream f;
      write_csv(f, results);
      write_file(csv, f.str());
    }
    return 0;
  } catch (const Error& e) {
    return report_error(e, err);
  } catch (const std::exception& e) {
    err << e.what() << "\n";
    return kExitRunFailure;
  }
}

}  // namespace stride::cli
