#pragma once
// "Module.field" and "Module.field=value": the one way a module parameter is named and changed
// from outside the module (scene <parameter>, timed changes, --set on every command, console).
#include <string>
#include <string_view>

namespace stride {

class Runtime;

struct ParameterKey {
  std::string module;  // "HipStrategy"
  std::string field;   // "kp_pitch", or a path such as "q_diagonal[2]"
};

struct ParameterOverride {
  ParameterKey key;
  std::string value;  // as text, parsed by the module's parameter reflection
};

// "Module.field"; throws stride::Error "<what> '<text>': expected Module.field".
ParameterKey parse_parameter_key(std::string_view text, const std::string& what);
// "Module.field=value"; throws stride::Error "<what> '<text>': expected Module.field=value".
ParameterOverride parse_parameter_override(std::string_view text, const std::string& what);

// The field=value text Runtime::set_parameters takes for the override's module.
std::string assignment_text(const ParameterOverride& o);
// Applies it; errors name the module and field (Runtime::set_parameters).
void apply_override(Runtime& runtime, const ParameterOverride& o);

}  // namespace stride
