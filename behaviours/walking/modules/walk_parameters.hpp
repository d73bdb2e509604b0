#pragma once
// Parameters of the open-loop walking modules (PatternWalk, ConventionalWalk): a speed preset of
// Sec. 4.3.4.2 with any Table 4.3 value overridden, plus the standing phase before the walk.
#include <array>
#include <limits>
#include <string_view>

#include "behaviours/walking/pattern/pattern_parameters.hpp"
#include "robot/framework/reflect.hpp"

namespace stride::behaviours {

enum class WalkPreset { slow, medium, fast };

}  // namespace stride::behaviours

namespace stride {
template <>
struct EnumNames<behaviours::WalkPreset> {
  static constexpr std::string_view type_name = "WalkPreset";
  static constexpr std::array<std::string_view, 3> names{"slow", "medium", "fast"};
};
}  // namespace stride

namespace stride::behaviours {

// Every Table 4.3 field is "nan" (or 0 for the step counts) to take the preset's value, or a
// value that replaces it; walking::validate() judges the result (walk_pattern_parameters()).
struct WalkParameters {
  STRIDE_FIELDS(WalkParameters);
  static constexpr double kFromPreset = std::numeric_limits<double>::quiet_NaN();

  STRIDE_FIELD(WalkPreset, preset) = WalkPreset::medium;
  STRIDE_FIELD(double, T_stride, "s") = kFromPreset;
  STRIDE_FIELD(double, tau_dsp) = kFromPreset;  // double-support ratio
  STRIDE_FIELD(double, A_l, "m") = kFromPreset;
  STRIDE_FIELD(double, z_min, "m") = kFromPreset;
  STRIDE_FIELD(double, z_max, "m") = kFromPreset;
  STRIDE_FIELD(double, d_0, "m") = kFromPreset;
  STRIDE_FIELD(double, H_foot, "m") = kFromPreset;
  STRIDE_FIELD(double, V_min, "m/s") = kFromPreset;         // m/s, rhythmic phase
  STRIDE_FIELD(double, V_max, "m/s") = kFromPreset;         // m/s, rhythmic phase
  STRIDE_FIELD(double, z_conventional, "m") = kFromPreset;  // m, ConventionalWalk's constant height
  // waist steps; the feet swing steps + 1 times
  STRIDE_FIELD(int, steps, "", Range{0, 10000}) = 0;
  STRIDE_FIELD(int, development_steps, "", Range{0, 1000}) = 0;
  STRIDE_FIELD(int, decay_steps, "", Range{0, 1000}) = 0;
  // s standing before the pattern starts
  STRIDE_FIELD(double, start_delay, "s", Range{0, 3600}) = 2.0;
  // s from the measured pose to the pattern's first pose
  STRIDE_FIELD(double, interpolation_time, "s", Range{0, 3600}) = 1.0;
  // Heading hold (walking/steps/heading_hold.hpp): share of the measured heading (WalkOdometry)
  // each step turns back, at most heading_per_step; 0: the thesis' walk, straight in the plan.
  STRIDE_FIELD(double, heading_gain, "", Range{0, 2}) = 0.0;
  STRIDE_FIELD(double, heading_per_step, "rad", Range{0, 0.3}) = 0.1;

  static constexpr std::string_view kTypeName = "WalkParameters";
};

// The preset with the overrides applied; throws stride::Error naming the offending parameter.
walking::PatternParameters walk_pattern_parameters(const WalkParameters& w);

// Field-wise equality where two "nan" (from the preset) fields are equal.
bool same_walk_parameters(const WalkParameters& a, const WalkParameters& b);

}  // namespace stride::behaviours
