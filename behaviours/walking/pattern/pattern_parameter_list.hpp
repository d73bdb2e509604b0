#pragma once
// What `stride pattern --set ?` lists: every settable pattern parameter with its unit, the range
// validate() accepts and its value in a parameter set.
#include <string>
#include <string_view>
#include <vector>

#include "behaviours/walking/pattern/pattern_parameters.hpp"

namespace stride::walking {

struct ParameterInfo {
  std::string_view name;     // as set_parameter() takes it (Table 4.3's names)
  std::string_view unit;     // "" for counts and ratios
  std::string range;         // what validate() accepts, e.g. "[0, 1)"
  std::string_view meaning;  // one phrase
  std::string (*value)(const PatternParameters&);
};

const std::vector<ParameterInfo>& parameter_info();

// A value as messages and lists show it (6 significant digits).
std::string parameter_text(double v);

// One line per parameter: "name = value [unit] in range: meaning".
std::vector<std::string> parameter_lines(const PatternParameters& p);

}  // namespace stride::walking
