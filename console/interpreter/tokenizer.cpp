#include "console/interpreter/tokenizer.hpp"

#include "robot/core/error.hpp"

namespace stride::console {

namespace {
bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}
}  // namespace

std::vector<std::string> tokenize(std::string_view line) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    if (i >= line.size() || line[i] == '#') break;
    std::string word;
    bool quoted = false;
    while (i < line.size() && (quoted || !blank(line[i]))) {
      const char c = line[i++];
      if (c == '"') {
        quoted = !quoted;
      } else if (c == '\\' && quoted && i < line.size()) {
        word += line[i++];  // \" and \\ inside quotes
      } else {
        word += c;
      }
    }
    if (quoted) throw Error("unterminated quote");
    words.push_back(std::move(word));
  }
  return words;
}

std::vector<std::string> split_statements(std::string_view line) {
  std::vector<std::string> out;
  std::string current;
  bool quoted = false;
  auto flush = [&] {
    const auto first = current.find_first_not_of(" \t\r\n");
    if (first != std::string::npos) {
      const auto last = current.find_last_not_of(" \t\r\n");
      out.push_back(current.substr(first, last - first + 1));
    }
    current.clear();
  };
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"') quoted = !quoted;
    if (c == '\\' && quoted && i + 1 < line.size()) {
      current += c;
      current += line[++i];
      continue;
    }
    if (c == ';' && !quoted) {
      flush();
      continue;
    }
    current += c;
  }
  flush();
  return out;
}

}  // namespace stride::console
