#pragma once
// Which module provides what, and parameter values, as a scene or robot configuration gives them.
#include <map>
#include <string>

namespace stride {

struct RuntimeConfig {
  std::map<std::string, std::string> providers;   // representation -> module
  std::map<std::string, std::string> parameters;  // "Module.field" -> text value
};

}  // namespace stride
