#include <cstdio>
#include <string>

#include "robot/framework/enum_names.hpp"
#include "robot/framework/module.hpp"

namespace stride {

std::string_view debug_switch_name(DebugSwitch s) {
  return enum_name(s);
}

void DebugRequest::print(std::string_view text) const {
  if (!on() || channel_->quiet.test(index_)) return;
  say(text);
}

void DebugRequest::say(std::string_view text) const {
  if (channel_->lines.size() >= kMaxDebugLines) {
    ++channel_->dropped_lines;
    return;
  }
  channel_->lines.push_back(channel_->names[index_] + ": " + std::string(text));
}

void DebugRequest::plot(std::string_view value, double v) const {
  if (!on()) return;
  const std::string key = channel_->names[index_] + "." + std::string(value);
  channel_->values.insert_or_assign(key, v);
}

void DebugRequest::show(std::initializer_list<std::pair<std::string_view, double>> values) const {
  if (!on()) return;
  std::string line;
  char number[32];
  for (const auto& [name, v] : values) {
    plot(name, v);
    std::snprintf(number, sizeof number, "%.5g", v);
    line.append(line.empty() ? "" : " ").append(name).append("=").append(number);
  }
  print(line);
}

void DebugRequest::stop(std::string_view reason) const {
  if (!on() || !channel_->stop.empty()) return;
  channel_->stop = channel_->names[index_] + ": " + std::string(reason);
}

}  // namespace stride
