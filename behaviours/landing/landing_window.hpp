#pragma once
// When one foot's landing control acts: from the planned foot heights (the walking pattern's leg
// targets) and the foot's measured load. A foot that the plan lifts is swinging; once the plan
// brings it back down, either its first measured load or its planned touch-down opens the landing
// window; after `hold_time` the offsets are handed back to the pattern over `return_time`.
#include <array>
#include <string_view>

#include "robot/framework/reflect.hpp"

namespace stride::behaviours {

enum class LandingStage { idle, swinging, landing, returning };

}  // namespace stride::behaviours

namespace stride {
template <>
struct EnumNames<behaviours::LandingStage> {
  static constexpr std::string_view type_name = "LandingStage";
  static constexpr std::array<std::string_view, 4> names{"idle", "swinging", "landing",
                                                         "returning"};
};
}  // namespace stride

namespace stride::behaviours {

struct LandingWindow {
  double lift_height = 0.004;    // m: planned height above the other sole that means swinging
  double touch_height = 0.0005;  // m: planned height that means the plan has touched down
  double contact_force = 5;      // N: measured load that means the sole has touched down
  double hold_time = 0.12;       // s the admittance acts after touch-down
  double return_time = 0.10;     // s to hand the offsets back to the pattern
};

struct FootLanding {
  LandingStage stage = LandingStage::idle;
  double since = 0;           // s, when the stage began
  double planned_height = 0;  // m, last frame's planned height (descending or not)
  double weight = 0;          // 0..1: how much of the admittance offset is applied
};

// One frame: the stage after `now`, given the foot's planned height above the other sole and its
// measured load.
FootLanding advance_landing(const FootLanding& f, const LandingWindow& w, double now,
                            double planned_height, double load);

}  // namespace stride::behaviours
