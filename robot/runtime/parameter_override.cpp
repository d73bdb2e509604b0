#include "robot/runtime/parameter_override.hpp"

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride {

ParameterKey parse_parameter_key(std::string_view text, const std::string& what) {
  const std::size_t dot = text.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == text.size() ||
      text.find('=') != std::string_view::npos)
    throw Error(what + " " + quote(text) + ": expected Module.field");
  return {std::string(text.substr(0, dot)), std::string(text.substr(dot + 1))};
}

ParameterOverride parse_parameter_override(std::string_view text, const std::string& what) {
  const std::size_t eq = text.find('=');
  const std::size_t dot = text.find('.');
  if (eq == std::string_view::npos || dot == std::string_view::npos || dot == 0 || eq < dot + 2 ||
      eq + 1 == text.size())
    throw Error(what + " " + quote(text) + ": expected Module.field=value");
  return {parse_parameter_key(text.substr(0, eq), what), std::string(text.substr(eq + 1))};
}

std::string assignment_text(const ParameterOverride& o) {
  return o.key.field + "=" + o.value;
}

void apply_override(Runtime& runtime, const ParameterOverride& o) {
  runtime.set_parameters(o.key.module, assignment_text(o));
}

}  // namespace stride
