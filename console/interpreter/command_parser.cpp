#include "console/interpreter/command_parser.hpp"

#include "console/interpreter/command_table.hpp"
#include "console/interpreter/edit_distance.hpp"
#include "console/interpreter/tokenizer.hpp"
#include "robot/core/error.hpp"

namespace stride::console {

Command parse_command(std::string_view line) {
  std::vector<std::string> words = tokenize(line);
  if (words.empty()) return {};
  Command c{words.front(), {words.begin() + 1, words.end()}};
  const CommandSpec* spec = find_command(c.name);
  if (!spec) {
    const std::string guess = nearest(c.name, command_names());
    throw Error("unknown command '" + c.name + "'" +
                (guess.empty() ? std::string(" (try help)") : "; did you mean '" + guess + "'?"));
  }
  const int n = static_cast<int>(c.args.size());
  if (n < spec->min_args || (spec->max_args >= 0 && n > spec->max_args))
    throw Error(c.name + ": expected " +
                (spec->max_args < 0 ? "at least " + std::to_string(spec->min_args)
                 : spec->min_args == spec->max_args
                     ? std::to_string(spec->min_args)
                     : std::to_string(spec->min_args) + " to " + std::to_string(spec->max_args)) +
                " argument(s), got " + std::to_string(n) + "; usage: " + std::string(spec->usage));
  if (spec->check) {
    try {
      spec->check(c.args);
    } catch (const Error& e) {
      throw Error(c.name + ": " + e.what() + "; usage: " + std::string(spec->usage));
    }
  }
  return c;
}

}  // namespace stride::console
