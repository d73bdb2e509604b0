#pragma once
// Which of the Ch. 7 strategies recovers a given initial CoM state (x0, xdot0), and why.
#include <string_view>

#include "behaviours/balance/ankle_strategy.hpp"
#include "behaviours/balance/combined_strategy.hpp"
#include "behaviours/balance/hip_strategy.hpp"
#include "robot/framework/reflect.hpp"

namespace stride::balance {

enum class Strategy { ankle, hip, combined, none };
std::string_view to_string(Strategy s);  // EnumNames<Strategy>

// Capture-point interval [lo, hi] of one strategy; at a given x0 it is the velocity interval
// [omega (lo - x0), omega (hi - x0)].
struct CaptureInterval {
  double lo = 0.0;
  double hi = 0.0;
  bool contains(double xi) const { return xi >= lo && xi <= hi; }
};

struct Classification {
  Strategy strategy = Strategy::none;  // least effort first: ankle, then hip, then combined
  double capture_point = 0.0;
  CaptureInterval ankle, hip, combined;  // of Eq. 7.13, Eq. 7.30, Eq. 7.37
  bool ankle_recovers = false, hip_recovers = false, combined_recovers = false;
  AnkleOpenLoopResult ankle_result;
  BangBangPlan hip_plan, combined_plan;  // switching times t1, t2 for each
};

Classification classify(const BalanceParams& p, const ComState& s0);

}  // namespace stride::balance

namespace stride {
template <>
struct EnumNames<balance::Strategy> {
  static constexpr std::string_view type_name = "Strategy";
  static constexpr std::array<std::string_view, 4> names{"ankle", "hip", "combined", "none"};
};
}  // namespace stride
