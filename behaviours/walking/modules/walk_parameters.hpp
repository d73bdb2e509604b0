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
  static constexpr double kFromPreset = std::numeric_limits<double>::quiet_NaN();

  WalkPreset preset = WalkPreset::medium;
  double T_stride = kFromPreset;        // s
  double tau_dsp = kFromPreset;         // double-support ratio
  double A_l = kFromPreset;             // m
  double z_min = kFromPreset;           // m
  double z_max = kFromPreset;           // m
  double d_0 = kFromPreset;             // m
  double H_foot = kFromPreset;          // m
  double V_min = kFromPreset;           // m/s, rhythmic phase
  double V_max = kFromPreset;           // m/s, rhythmic phase
  double z_conventional = kFromPreset;  // m, ConventionalWalk's constant height
  int steps = 0;                        // waist steps; the feet swing steps + 1 times
  int development_steps = 0;
  int decay_steps = 0;
  double start_delay = 2.0;         // s standing before the pattern starts
  double interpolation_time = 1.0;  // s from the measured pose to the pattern's first pose
  // Heading hold (walking/steps/heading_hold.hpp): share of the measured heading (WalkOdometry)
  // each step turns back, at most heading_per_step; 0: the thesis' walk, straight in the plan.
  double heading_gain = 0.0;
  double heading_per_step = 0.1;  // rad

  static constexpr std::string_view kTypeName = "WalkParameters";
  static constexpr auto fields() {
    using P = WalkParameters;
    return std::make_tuple(field("preset", &P::preset), field("T_stride", &P::T_stride, "s"),
                           field("tau_dsp", &P::tau_dsp), field("A_l", &P::A_l, "m"),
                           field("z_min", &P::z_min, "m"), field("z_max", &P::z_max, "m"),
                           field("d_0", &P::d_0, "m"), field("H_foot", &P::H_foot, "m"),
                           field("V_min", &P::V_min, "m/s"), field("V_max", &P::V_max, "m/s"),
                           field("z_conventional", &P::z_conventional, "m"),
                           field("steps", &P::steps, "", Range{0, 10000}),
                           field("development_steps", &P::development_steps, "", Range{0, 1000}),
                           field("decay_steps", &P::decay_steps, "", Range{0, 1000}),
                           field("start_delay", &P::start_delay, "s", Range{0, 3600}),
                           field("interpolation_time", &P::interpolation_time, "s", Range{0, 3600}),
                           field("heading_gain", &P::heading_gain, "", Range{0, 2}),
                           field("heading_per_step", &P::heading_per_step, "rad", Range{0, 0.3}));
  }
};

// The preset with the overrides applied; throws stride::Error naming the offending parameter.
walking::PatternParameters walk_pattern_parameters(const WalkParameters& w);

// Field-wise equality where two "nan" (from the preset) fields are equal.
bool same_walk_parameters(const WalkParameters& a, const WalkParameters& b);

}  // namespace stride::behaviours
