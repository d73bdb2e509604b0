#include "console/experiments/parameter_overrides.hpp"

#include "robot/core/error.hpp"

namespace stride::experiments {

std::pair<std::string, std::string> parse_parameter_override(const std::string& text) {
  const std::size_t dot = text.find('.'), eq = text.find('=');
  if (dot == std::string::npos || eq == std::string::npos || dot == 0 || eq < dot + 2 ||
      eq + 1 == text.size())
    throw UsageError("stride experiment: --set '" + text + "': expected Module.field=value");
  return {text.substr(0, dot), text.substr(dot + 1)};
}

WalkSetup with_overrides(const ExperimentOptions& o, WalkSetup setup) {
  setup.parameters.insert(setup.parameters.begin(), o.parameters.begin(), o.parameters.end());
  return setup;
}

}  // namespace stride::experiments
