#pragma once
// `help <word>` and `stride help <word>`: what a word finds, best first.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace stride::console {

struct HelpEntry {
  std::string name;  // command or key namespace, e.g. "log" or "provider:"
  std::string text;  // its usage and summary
};

// The entries named `word`; if none, those with `word` as a whole word in their text; if none,
// those containing it anywhere. Indices in entry order.
std::vector<std::size_t> find_help(const std::vector<HelpEntry>& entries, std::string_view word);

}  // namespace stride::console
