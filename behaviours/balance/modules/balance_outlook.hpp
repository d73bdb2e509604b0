#pragma once
// BalanceOutlook: which Ch. 7 strategies would recover the robot from its estimated CoM state
// now (balance::classify, Sec. 7.6), every frame, so a sweep or `watch` can read the prediction
// at the moment a push ends and compare it with what the robot then does.
//   ComState, BalanceModel -> BalancePrediction
// Choose it with `mr BalancePrediction BalanceOutlook` (a sweep: provider:BalancePrediction).
#include <cstdint>
#include <string_view>

#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"

namespace stride {

struct BalancePrediction {
  bool valid = false;              // false until ComState and BalanceModel are
  double capture_point = 0;        // x0 + xdot0 / omega in the ground frame, m
  bool ankle_recovers = false;     // the ankle alone (Eq. 7.13)
  bool hip_recovers = false;       // the hip's bang-bang profile alone (Eq. 7.30)
  bool combined_recovers = false;  // both together (Eq. 7.37)
  // The least effort that recovers: 0 ankle, 1 hip, 2 combined, 3 none (balance::Strategy).
  std::int32_t strategy = 3;
  // The boundaries as capture-point intervals [lo, hi] (in the (x, xdot) plane the lines
  // xdot = omega (lo - x) and omega (hi - x)), for phase portraits against them.
  double omega = 0;                         // 1/s
  double ankle_lo = 0, ankle_hi = 0;        // m, bounds of Eq. 7.13
  double hip_lo = 0, hip_hi = 0;            // m, bounds of Eq. 7.30
  double combined_lo = 0, combined_hi = 0;  // m, bounds of Eq. 7.37

  static constexpr std::string_view kTypeName = "BalancePrediction";
  static constexpr auto fields() {
    using P = BalancePrediction;
    return std::make_tuple(
        field("valid", &P::valid), field("capture_point", &P::capture_point, "m"),
        field("ankle_recovers", &P::ankle_recovers), field("hip_recovers", &P::hip_recovers),
        field("combined_recovers", &P::combined_recovers), field("strategy", &P::strategy),
        field("omega", &P::omega, "1/s"), field("ankle_lo", &P::ankle_lo, "m"),
        field("ankle_hi", &P::ankle_hi, "m"), field("hip_lo", &P::hip_lo, "m"),
        field("hip_hi", &P::hip_hi, "m"), field("combined_lo", &P::combined_lo, "m"),
        field("combined_hi", &P::combined_hi, "m"));
  }
};

namespace behaviours {

// The hip torques the models assume; defaults those of HipBalance.
struct BalanceOutlookParameters {
  double tau_forward = 14;    // N m
  double tau_backward = -14;  // N m

  static constexpr std::string_view kTypeName = "BalanceOutlookParameters";
  static constexpr auto fields() {
    using P = BalanceOutlookParameters;
    return std::make_tuple(field("tau_forward", &P::tau_forward, "N*m", Range{0, 100}),
                           field("tau_backward", &P::tau_backward, "N*m", Range{-100, 0}));
  }
};

void register_balance_outlook(ModuleRegistry& registry);

}  // namespace behaviours
}  // namespace stride
