#include "robot/runtime/controller_keys.hpp"

#include <algorithm>
#include <charconv>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "robot/framework/enum_names.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride {

namespace {
std::string debug_value(const Runtime& rt, const std::string& key) {
  const std::string name = key.substr(6);
  const auto& values = rt.debug_values();
  if (const auto it = values.find(name); it != values.end()) return debug_value_text(it->second);
  const auto dot = name.rfind('.');
  const std::string request = name.substr(0, dot);
  std::string emitted;  // the request's values so far
  for (const auto& [value, v] : values)
    if (value.starts_with(request + ".")) emitted += (emitted.empty() ? "" : ", ") + value;
  for (const auto& [n, state] : rt.debug_requests()) {
    if (n != request) continue;
    if (!emitted.empty()) throw Error(key + ": no such value (" + emitted + ")");
    if (state == DebugSwitch::Off) throw Error(key + ": switch it on first (dr " + n + " on)");
    return "nan";  // on, but its module has not run since
  }
  throw Error(key + ": no debug request " + quote(request) + " (dr ? lists them)");
}
}  // namespace

std::string debug_value_text(double v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

std::optional<DebugSwitch> debug_switch_named(std::string_view name) {
  return enum_from_name<DebugSwitch>(name);
}

bool is_controller_key(std::string_view key) {
  return key.starts_with("provider:") || key.starts_with("override:") || key.starts_with("debug:");
}

std::string controller_value(const Runtime& rt, const std::string& key) {
  if (key.starts_with("debug:")) return debug_value(rt, key);
  if (!is_controller_key(key)) throw Error("key " + quote(key) + ": not a controller key");
  const std::string rep = key.substr(key.find(':') + 1);
  const auto names = rt.representation_names();
  if (std::find(names.begin(), names.end(), rep) == names.end())
    throw Error("no representation " + quote(rep) + " on the blackboard");
  if (key.starts_with("override:")) {
    const auto it = rt.overrides().find(rep);
    return it == rt.overrides().end() ? "(none)" : it->second;
  }
  const std::string by = rt.provider_of(rep);
  return by.empty() ? "(built-in)" : by;
}

}  // namespace stride
