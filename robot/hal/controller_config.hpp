#pragma once
// A robot's <controller> section as plain data: providers, parameters and timed changes. The same
// section configures a robot in a scene and the physical robot (`stride robot --config`).
#include <map>
#include <string>
#include <vector>

#include "robot/core/xml_element.hpp"

namespace stride {

// A change to a running controller at a given time: a provider swap or a parameter value.
struct ControllerChange {
  double time = 0;  // s since the controller started
  enum class Kind { Provider, Parameter } kind = Kind::Parameter;
  std::string first, second;  // provider: representation, module; parameter: "Module.field", value
  std::string file;
  int line = 0;

  // The same change, wherever it was written.
  bool operator==(const ControllerChange& o) const {
    return time == o.time && kind == o.kind && first == o.first && second == o.second;
  }
};

struct ControllerConfig {
  std::map<std::string, std::string> providers;   // representation -> module
  std::map<std::string, std::string> parameters;  // "Module.field" -> text value
  std::vector<ControllerChange> changes;          // in time order (stable for equal times)

  bool operator==(const ControllerConfig&) const = default;
};

// Reads a <controller> element: <provider representation module>, <parameter module field
// value> and <at time> holding providers and parameters. Errors name file:line.
ControllerConfig parse_controller(const XmlElement& e);

}  // namespace stride
