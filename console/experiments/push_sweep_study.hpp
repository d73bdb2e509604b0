#pragma once
// Thesis Ch. 7's prediction against the simulation, one push at a time: the standing robot under
// one balance strategy is pushed on the torso once per (impulse, direction) in a freshly loaded
// scene; balance::classify predicts the outcome from the post-push CoM state (the estimator's and
// the simulator's), and the next seconds show what the robot does. The pushes run as jobs of the
// sweep engine's executors (console/sweep/ordered_jobs). `stride push-sweep` prints the result.
// The Ch. 7 models are sagittal: the CoM state along x is classified, so directions other than
// 0 (forward) and 180 (backward) add lateral motion the prediction does not see.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "behaviours/balance/strategy_classifier.hpp"
#include "robot/framework/reflect.hpp"
#include "robot/runtime/parameter_override.hpp"

namespace stride::experiments {

// One sweep's pushes at most: each is a few simulated seconds, so 2000 take an hour or more.
inline constexpr std::size_t kMaxPushes = 2000;

// Feet moving more than this means the robot stepped or slid: not a recovery in place.
inline constexpr double kMaxFootMotion = 0.02;

struct PushSweepOptions {
  std::string scene;
  std::string strategy = "ankle";  // a name of behaviours::kBalanceStrategyModules
  std::vector<double> impulses, directions;
  double duration = 0.05, settle = 1.5, observe = 3.0;
  // The filter needs a few frames to follow the jump in velocity; the classes are invariant
  // along saturated trajectories, so classifying a little after the push is consistent.
  double estimate_delay = 0.03;
  std::optional<std::uint64_t> seed;
  std::vector<ParameterOverride> parameters;  // --set "Module.field=value ..."
};

struct PushOutcome {
  STRIDE_FIELDS(PushOutcome);
  STRIDE_FIELD(double, impulse, "N*s") = 0;
  STRIDE_FIELD(double, direction, "deg") = 0;
  // estimated CoM state along x, ground frame
  STRIDE_FIELD(double, x_est, "m") = 0;
  STRIDE_FIELD(double, v_est, "m/s") = 0;
  // the simulator's
  STRIDE_FIELD(double, x_true, "m") = 0;
  STRIDE_FIELD(double, v_true, "m/s") = 0;
  STRIDE_FIELD(balance::Strategy, predicted) = balance::Strategy::none;
  STRIDE_FIELD(balance::Strategy, predicted_true) = balance::Strategy::none;
  // the chosen strategy's region contains the estimate
  STRIDE_FIELD(bool, expected_recovery) = false;
  STRIDE_FIELD(bool, truth_expects_recovery) = false;  // the same from the simulator's CoM state
  STRIDE_FIELD(bool, fell) = false;
  STRIDE_FIELD(double, foot_motion, "m") = 0;  // m, the larger move of the two feet

  bool recovered() const { return !fell && foot_motion <= kMaxFootMotion; }
  bool agree() const { return expected_recovery == recovered(); }

  // Reflected: a push comes back from its worker in the framework's binary encoding.
  static constexpr std::string_view kTypeName = "PushOutcome";
};

// Throws stride::UsageError for an unknown strategy or out-of-range times and counts.
void check_push_sweep(const PushSweepOptions& options);

// One push in a freshly loaded scene. Throws stride::InputError for a scene without controller.
PushOutcome run_push(const PushSweepOptions& options, double impulse, double direction);

// Every impulse x direction (impulse outermost), over up to `jobs` workers; the same whatever
// `jobs` is.
std::vector<PushOutcome> run_push_sweep(const PushSweepOptions& options, int jobs = 1);

}  // namespace stride::experiments
