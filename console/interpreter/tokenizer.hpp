#pragma once
// Splitting console text into words: blanks separate, double quotes group, '#' at a word start
// begins a comment, ';' separates commands on one line (for `stride -c "a; b"`).
#include <string>
#include <string_view>
#include <vector>

namespace stride::console {

// Words of one command. Throws stride::Error on an unterminated quote.
std::vector<std::string> tokenize(std::string_view line);

// Commands of one line split at ';' outside quotes, each trimmed; empty pieces dropped.
std::vector<std::string> split_statements(std::string_view line);

}  // namespace stride::console
