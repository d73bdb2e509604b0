#include "behaviours/walking/pattern/pattern_parameters.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>

#include "behaviours/walking/pattern/pattern_parameter_list.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/quote.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::walking {

namespace {

std::string number(double v) {
  return parameter_text(v);
}

bool finite_positive(double v) {
  return std::isfinite(v) && v > 0.0;
}

std::optional<std::string> level_error(const SpeedLevel& l, const std::string& what) {
  if (!std::isfinite(l.V_min) || l.V_min < 0.0)
    return what + " V_min must be >= 0 m/s (got " + number(l.V_min) + ")";
  if (!std::isfinite(l.V_max) || l.V_max < l.V_min)
    return what + " V_max must be >= V_min = " + number(l.V_min) + " m/s (got " + number(l.V_max) +
           ")";
  return std::nullopt;
}

double parse_double(const std::string& name, const std::string& value) {
  return parse_number(value, "parameter " + name);
}

int parse_int(const std::string& name, const std::string& value) {
  return static_cast<int>(parse_integer(value, "parameter " + name, -1'000'000, 1'000'000));
}

// "vmin:vmax,vmin:vmax" (empty string = no intermediate level).
std::vector<SpeedLevel> parse_levels(const std::string& name, const std::string& value) {
  std::vector<SpeedLevel> levels;
  std::size_t start = 0;
  while (start < value.size()) {
    std::size_t comma = value.find(',', start);
    if (comma == std::string::npos) comma = value.size();
    const std::string item = value.substr(start, comma - start);
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos)
      throw Error("parameter " + name + ": expected vmin:vmax[,vmin:vmax...], got " + quote(value));
    levels.push_back(
        {parse_double(name, item.substr(0, colon)), parse_double(name, item.substr(colon + 1))});
    start = comma + 1;
  }
  return levels;
}

}  // namespace

double PatternParameters::omega() const {
  return 2.0 * std::numbers::pi / T_stride;
}

double max_waist_height() {
  return nao::kHipOffsetZ + nao::kThighLength + nao::kTibiaLength + nao::kFootHeight;
}

std::vector<SpeedLevel> linear_levels(const SpeedLevel& target, int n) {
  std::vector<SpeedLevel> levels;
  for (int k = 1; k < n; ++k) {
    const double f = static_cast<double>(k) / n;
    levels.push_back({f * target.V_min, f * target.V_max});
  }
  return levels;
}

std::optional<std::string> validation_error(const PatternParameters& p) {
  if (!finite_positive(p.T_stride))
    return "T_stride must be > 0 s (got " + number(p.T_stride) + ")";
  if (!std::isfinite(p.tau_dsp) || p.tau_dsp < 0.0 || p.tau_dsp >= 1.0)
    return "tau_dsp must be in [0, 1) (got " + number(p.tau_dsp) + ")";
  if (!std::isfinite(p.A_l) || p.A_l < 0.0) return "A_l must be >= 0 m (got " + number(p.A_l) + ")";
  if (!finite_positive(p.z_min)) return "z_min must be > 0 m (got " + number(p.z_min) + ")";
  if (!std::isfinite(p.z_max) || p.z_max < p.z_min)
    return "z_max must be >= z_min = " + number(p.z_min) + " m (got " + number(p.z_max) + ")";
  if (p.z_max > max_waist_height())
    return "z_max = " + number(p.z_max) + " m is beyond the leg's reach: the torso origin is at " +
           "most " + number(max_waist_height()) + " m above the sole";
  if (!finite_positive(p.z_conventional) || p.z_conventional > max_waist_height())
    return "z_conventional must be in (0, " + number(max_waist_height()) + "] m (got " +
           number(p.z_conventional) + ")";
  // Mid single support: the waist is over the support foot in x but A_l aside of it in y.
  const double leg = nao::kThighLength + nao::kTibiaLength;
  const double hip_to_ankle =
      std::hypot(p.z_max - nao::kHipOffsetZ - nao::kFootHeight, p.A_l + nao::kHipOffsetY - p.d_0);
  if (hip_to_ankle > leg)
    return "z_max = " + number(p.z_max) + " m with A_l = " + number(p.A_l) +
           " m and d_0 = " + number(p.d_0) +
           " m is beyond the leg's reach at mid single support (hip-ankle " + number(hip_to_ankle) +
           " m > " + number(leg) + " m)";
  // The soles' inner edges must not overlap (Table 4.3: foot collision avoidance distance).
  const double inner_edge = 0.5 * nao::kSoleWidth - nao::kSoleCentreYLeft;
  if (!std::isfinite(p.d_0) || p.d_0 < inner_edge)
    return "d_0 must be >= " + number(inner_edge) + " m so the soles do not overlap (got " +
           number(p.d_0) + ")";
  if (!finite_positive(p.H_foot)) return "H_foot must be > 0 m (got " + number(p.H_foot) + ")";
  if (!finite_positive(p.gravity))
    return "gravity must be > 0 m/s^2 (got " + number(p.gravity) + ")";
  if (auto e = level_error(p.rhythmic, "rhythmic")) return e;
  for (std::size_t i = 0; i < p.development.size(); ++i)
    if (auto e = level_error(p.development[i], "development level " + std::to_string(i + 1)))
      return e;
  for (std::size_t i = 0; i < p.decay.size(); ++i)
    if (auto e = level_error(p.decay[i], "decay level " + std::to_string(i + 1))) return e;
  // The cycloid's alpha (Eq. 3.15) is the step length over pi; zero makes delta undefined.
  if (p.rhythmic.V_max * p.T_d() + p.rhythmic.V_min * p.T_s() <= 0.0)
    return "V_min and V_max are both 0: alpha (Eq. 3.15) is 0 and delta = H_foot/(2 alpha) is "
           "undefined";
  if (p.steps < 2) return "steps must be >= 2 (got " + std::to_string(p.steps) + ")";
  if (p.rhythmic_steps() < 0)
    return "steps = " + std::to_string(p.steps) + " is fewer than the " +
           std::to_string(p.development_steps()) + " development + " +
           std::to_string(p.decay_steps()) + " decay steps";
  return std::nullopt;
}

void validate(const PatternParameters& p) {
  if (auto e = validation_error(p)) throw Error(*e);
}

PatternParameters preset(const std::string& name) {
  PatternParameters p;  // Table 4.3 defaults
  if (name == "slow" || name == "medium" || name == "fast") {
    // Sec. 4.3.4.2: waist height and A_l per speed; V_min/V_max chosen for the reported speeds.
    if (name == "slow") {
      p.A_l = 0.001, p.z_min = 0.327, p.z_max = 0.329, p.rhythmic = {0.08, 0.09};
    } else if (name == "medium") {
      p.A_l = 0.001, p.z_min = 0.323, p.z_max = 0.325, p.rhythmic = {0.18, 0.19};
    } else {
      p.A_l = 0.0005, p.z_min = 0.313, p.z_max = 0.315, p.rhythmic = {0.23, 0.24};
    }
    p.development = linear_levels(p.rhythmic, 3);
    p.decay = linear_levels(p.rhythmic, 2);
    return p;
  }
  if (name == "fig3.14" || name == "fig3.16") {
    // Chapter 3 plotting sets; tau_dsp and (for Fig. 3.16) the heights are not printed there.
    // Fig. 3.14's 0.330/0.332 m are lowered by 1 mm: with A_l = 0.025 m the support ankle would
    // be 0.2034 m from the hip at mid single support, beyond this model's 0.2029 m leg.
    p.T_stride = 1.16, p.tau_dsp = 0.2, p.A_l = 0.025, p.H_foot = 0.026, p.steps = 20;
    if (name == "fig3.14") {
      p.z_min = 0.329, p.z_max = 0.331, p.rhythmic = {0.09, 0.10};
      p.development = {{0.01, 0.02}, {0.03, 0.04}};
      p.decay = {{0.03, 0.04}, {0.01, 0.02}};
    } else {
      p.z_min = 0.300, p.z_max = 0.305, p.rhythmic = {0.23, 0.24};  // reachable 0.136 m steps
      p.development = linear_levels(p.rhythmic, 3);
      p.decay = linear_levels(p.rhythmic, 3);
    }
    return p;
  }
  // Table 4.4 (energy comparison, Sec. 4.3.4.3): mean speed, step height and waist heights; the
  // conventional pattern of Table 4.5 keeps z_conventional = 0.318 m and a 2 cm step height.
  struct EnergyRow {
    const char* name;
    double speed, H_foot, z_min, z_max;
  };
  for (const EnergyRow& r : {EnergyRow{"table4.4-5", 0.0521, 0.020, 0.331, 0.332},
                             EnergyRow{"table4.4-10", 0.0991, 0.020, 0.331, 0.332},
                             EnergyRow{"table4.4-15", 0.1639, 0.024, 0.326, 0.327},
                             EnergyRow{"table4.4-20", 0.2004, 0.024, 0.321, 0.322}}) {
    if (name != r.name) continue;
    p.H_foot = r.H_foot, p.z_min = r.z_min, p.z_max = r.z_max, p.steps = 80;  // 20 s
    p.rhythmic = {r.speed - 0.005, r.speed + 0.005};
    p.development = linear_levels(p.rhythmic, 3);
    p.decay = linear_levels(p.rhythmic, 2);
    return p;
  }
  throw Error("unknown pattern preset '" + name +
              "' (slow, medium, fast, fig3.14, fig3.16, table4.4-5, -10, -15, -20)");
}

std::vector<std::string> preset_names() {
  return {"slow",       "medium",      "fast",        "fig3.14",    "fig3.16",
          "table4.4-5", "table4.4-10", "table4.4-15", "table4.4-20"};
}

void set_parameter(PatternParameters& p, const std::string& name, const std::string& value) {
  if (name == "T_stride")
    p.T_stride = parse_double(name, value);
  else if (name == "tau_dsp")
    p.tau_dsp = parse_double(name, value);
  else if (name == "A_l")
    p.A_l = parse_double(name, value);
  else if (name == "A_s")
    p.z_min = p.z_max - 2.0 * parse_double(name, value);
  else if (name == "z_min")
    p.z_min = parse_double(name, value);
  else if (name == "z_max")
    p.z_max = parse_double(name, value);
  else if (name == "d_0")
    p.d_0 = parse_double(name, value);
  else if (name == "H_foot")
    p.H_foot = parse_double(name, value);
  else if (name == "V_min")
    p.rhythmic.V_min = parse_double(name, value);
  else if (name == "V_max")
    p.rhythmic.V_max = parse_double(name, value);
  else if (name == "gravity")
    p.gravity = parse_double(name, value);
  else if (name == "z_conventional")
    p.z_conventional = parse_double(name, value);
  else if (name == "steps")
    p.steps = parse_int(name, value);
  else if (name == "development_levels")
    p.development = parse_levels(name, value);
  else if (name == "decay_levels")
    p.decay = parse_levels(name, value);
  else if (name == "development_steps" || name == "decay_steps") {
    const int n = parse_int(name, value);
    if (n < 1) throw Error("parameter " + name + ": must be >= 1 (got " + value + ")");
    (name == "development_steps" ? p.development : p.decay) = linear_levels(p.rhythmic, n);
  } else {
    throw Error("unknown pattern parameter " + quote(name));
  }
}

std::vector<std::string> parameter_names() {
  std::vector<std::string> names;
  for (const auto& i : parameter_info()) names.emplace_back(i.name);
  return names;
}

}  // namespace stride::walking
