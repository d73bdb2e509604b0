#pragma once
// One line of console text -> a checked command. Throws stride::Error with a one-line message
// (unknown command with the nearest suggestion, wrong arity with the usage, bad argument).
#include <string>
#include <string_view>
#include <vector>

namespace stride::console {

struct Command {
  std::string name;  // empty for a blank line or a comment
  std::vector<std::string> args;
};

Command parse_command(std::string_view line);

}  // namespace stride::console
