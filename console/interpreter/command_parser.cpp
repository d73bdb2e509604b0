#include "console/interpreter/command_parser.hpp"

#include "console/interpreter/command_table.hpp"
#include "console/interpreter/edit_distance.hpp"
#include "console/interpreter/tokenizer.hpp"
#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"

namespace stride::console {
namespace {

// Quoted words may hold newlines or control bytes; errors stay one printable line.
std::string one_line(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    if (ch == '\n')
      out += "\\n";
    else if (ch == '\t')
      out += "\\t";
    else if (u < 0x20 || u == 0x7f)
      out += std::string("\\x") + kHex[u >> 4] + kHex[u & 15];
    else
      out += ch;
  }
  return out;
}

Command parse_checked(std::string_view line) {
  std::vector<std::string> words = tokenize(line);
  if (words.empty()) return {};
  Command c{words.front(), {words.begin() + 1, words.end()}};
  const CommandSpec* spec = find_command(c.name);
  if (!spec) {
    const std::string guess = nearest(c.name, command_names());
    throw Error("unknown command " + quote(c.name) +
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

}  // namespace

Command parse_command(std::string_view line) {
  try {
    return parse_checked(line);
  } catch (const Error& e) {
    throw InputError(one_line(e.what()));  // a line that does not parse is bad command text
  }
}

}  // namespace stride::console
