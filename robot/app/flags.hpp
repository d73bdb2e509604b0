#pragma once
// `--flag value` command lines for the robot-side programs, read strictly: an unknown or repeated
// flag, or one without its value, is a one-line error naming the command.
#include <initializer_list>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stride {

struct Flags {
  std::map<std::string, std::string, std::less<>> values;
  std::vector<std::string> positional;

  std::string value_or(std::string_view flag, const std::string& fallback) const {
    auto it = values.find(flag);
    return it == values.end() ? fallback : it->second;
  }
};

Flags read_flags(std::span<const std::string> args, std::initializer_list<std::string_view> flags,
                 const std::string& command);

}  // namespace stride
