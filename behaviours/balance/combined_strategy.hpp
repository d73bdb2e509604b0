#pragma once
// Combined ankle + hip strategy with the bang-bang hip torque (thesis Sec. 7.5.1).
#include "behaviours/balance/hip_strategy.hpp"

namespace stride::balance {

// Capture-point interval (Eq. 7.37) recoverable with the ZMP at a sole border plus the hip.
struct CombinedBoundaries {
  double backward = 0.0;  // zmp_min + backward hip shift
  double forward = 0.0;   // zmp_max + forward hip shift
};
CombinedBoundaries combined_boundaries(const BalanceParams& p);

// Sec. 7.5.1: the ankle holds the ZMP at the border nearest the capture point and the hip covers
// the rest (Eq. 7.36 solved for T = t1). Inside the sole the ankle alone suffices: zero profile.
BangBangPlan plan_combined(const BalanceParams& p, const ComState& s0);

}  // namespace stride::balance
