#include "console/experiments/parameter_overrides.hpp"

#include "robot/core/error.hpp"
#include "robot/runtime/parameter_override.hpp"

namespace stride::experiments {

std::pair<std::string, std::string> parse_parameter_override(const std::string& text) {
  try {
    const ParameterOverride o = stride::parse_parameter_override(text, "stride experiment: --set");
    return {o.key.module, assignment_text(o)};
  } catch (const Error& e) {
    throw UsageError(e.what());  // a malformed --set is a wrong command line
  }
}

WalkSetup with_overrides(const ExperimentOptions& o, WalkSetup setup) {
  setup.parameters.insert(setup.parameters.begin(), o.parameters.begin(), o.parameters.end());
  return setup;
}

}  // namespace stride::experiments
