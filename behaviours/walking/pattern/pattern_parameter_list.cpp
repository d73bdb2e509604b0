#include "behaviours/walking/pattern/pattern_parameter_list.hpp"

#include <sstream>

#include "robot/nao/nao_dimensions.hpp"

namespace stride::walking {

std::string parameter_text(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

namespace {

std::string levels_text(const std::vector<SpeedLevel>& levels) {
  std::string out;
  for (const auto& l : levels)
    out += (out.empty() ? "" : ",") + parameter_text(l.V_min) + ":" + parameter_text(l.V_max);
  return out.empty() ? "(none)" : out;
}

}  // namespace

const std::vector<ParameterInfo>& parameter_info() {
  using P = PatternParameters;
  static const std::vector<ParameterInfo> list = {
      {"T_stride", "s", "> 0", "walking period, two steps",
       [](const P& p) { return parameter_text(p.T_stride); }},
      {"tau_dsp", "", "[0, 1)", "double-support ratio of a step",
       [](const P& p) { return parameter_text(p.tau_dsp); }},
      {"A_l", "m", ">= 0", "lateral swing amplitude of the waist (Eq. 3.9)",
       [](const P& p) { return parameter_text(p.A_l); }},
      {"A_s", "m", ">= 0", "half the waist's vertical travel: sets z_min = z_max - 2 A_s",
       [](const P& p) { return parameter_text(0.5 * (p.z_max - p.z_min)); }},
      {"z_min", "m", "> 0", "lowest torso-origin height, double support (Eq. 3.10)",
       [](const P& p) { return parameter_text(p.z_min); }},
      {"z_max", "m", "[z_min, " + parameter_text(max_waist_height()) + "]",
       "highest torso-origin height, mid single support",
       [](const P& p) { return parameter_text(p.z_max); }},
      {"d_0", "m",
       ">= " + parameter_text(0.5 * nao::kSoleWidth - nao::kSoleCentreYLeft) + " (soles apart)",
       "lateral distance of each foot from the walking line",
       [](const P& p) { return parameter_text(p.d_0); }},
      {"H_foot", "m", "> 0", "maximum swing-foot elevation (Eq. 3.11)",
       [](const P& p) { return parameter_text(p.H_foot); }},
      {"V_min", "m/s", ">= 0", "rhythmic waist speed at mid single support (Eq. 3.1)",
       [](const P& p) { return parameter_text(p.rhythmic.V_min); }},
      {"V_max", "m/s", ">= V_min", "rhythmic waist speed in double support (Eq. 3.1)",
       [](const P& p) { return parameter_text(p.rhythmic.V_max); }},
      {"steps", "", ">= 2, >= development + decay steps", "waist steps of the walk",
       [](const P& p) { return std::to_string(p.steps); }},
      {"development_steps", "", ">= 1", "steps from rest to the rhythmic speed (even levels)",
       [](const P& p) { return std::to_string(p.development_steps()); }},
      {"decay_steps", "", ">= 1", "steps from the rhythmic speed to rest (even levels)",
       [](const P& p) { return std::to_string(p.decay_steps()); }},
      {"development_levels", "m/s", "vmin:vmax,... each >= 0", "intermediate speed levels up",
       [](const P& p) { return levels_text(p.development); }},
      {"decay_levels", "m/s", "vmin:vmax,... each >= 0", "intermediate speed levels down",
       [](const P& p) { return levels_text(p.decay); }},
      {"gravity", "m/s^2", "> 0", "gravity of the ZMP (Eq. 3.16)",
       [](const P& p) { return parameter_text(p.gravity); }},
      {"z_conventional", "m", "(0, " + parameter_text(max_waist_height()) + "]",
       "torso height of the bent-knee pattern (Table 4.5)",
       [](const P& p) { return parameter_text(p.z_conventional); }},
  };
  return list;
}

std::vector<std::string> parameter_lines(const PatternParameters& p) {
  std::vector<std::string> lines;
  for (const auto& i : parameter_info()) {
    std::string line = std::string(i.name) + " = " + i.value(p);
    if (!i.unit.empty()) line += " [" + std::string(i.unit) + "]";
    line += " in " + i.range + ": " + std::string(i.meaning);
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace stride::walking
