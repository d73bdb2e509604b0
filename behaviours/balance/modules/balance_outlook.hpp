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
  STRIDE_FIELDS(BalancePrediction);
  STRIDE_FIELD(bool, valid) = false;              // false until ComState and BalanceModel are
  STRIDE_FIELD(double, capture_point, "m") = 0;   // x0 + xdot0 / omega in the ground frame, m
  STRIDE_FIELD(bool, ankle_recovers) = false;     // the ankle alone (Eq. 7.13)
  STRIDE_FIELD(bool, hip_recovers) = false;       // the hip's bang-bang profile alone (Eq. 7.30)
  STRIDE_FIELD(bool, combined_recovers) = false;  // both together (Eq. 7.37)
  // The least effort that recovers: 0 ankle, 1 hip, 2 combined, 3 none (balance::Strategy).
  STRIDE_FIELD(std::int32_t, strategy) = 3;
  // The boundaries as capture-point intervals [lo, hi] (in the (x, xdot) plane the lines
  // xdot = omega (lo - x) and omega (hi - x)), for phase portraits against them.
  STRIDE_FIELD(double, omega, "1/s") = 0;
  // m, bounds of Eq. 7.13
  STRIDE_FIELD(double, ankle_lo, "m") = 0;
  STRIDE_FIELD(double, ankle_hi, "m") = 0;
  // m, bounds of Eq. 7.30
  STRIDE_FIELD(double, hip_lo, "m") = 0;
  STRIDE_FIELD(double, hip_hi, "m") = 0;
  // m, bounds of Eq. 7.37
  STRIDE_FIELD(double, combined_lo, "m") = 0;
  STRIDE_FIELD(double, combined_hi, "m") = 0;

  static constexpr std::string_view kTypeName = "BalancePrediction";
};

namespace behaviours {

// The hip torques the models assume; defaults those of HipBalance.
struct BalanceOutlookParameters {
  STRIDE_FIELDS(BalanceOutlookParameters);
  STRIDE_FIELD(double, tau_forward, "N*m", Range{0, 100}) = 14;     // N m
  STRIDE_FIELD(double, tau_backward, "N*m", Range{-100, 0}) = -14;  // N m

  static constexpr std::string_view kTypeName = "BalanceOutlookParameters";
};

void register_balance_outlook(ModuleRegistry& registry);

}  // namespace behaviours
}  // namespace stride
