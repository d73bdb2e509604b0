#include "console/interpreter/help_search.hpp"

#include <cctype>

namespace stride::console {

namespace {

bool word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
}

bool has_whole_word(std::string_view text, std::string_view word) {
  for (auto at = text.find(word); at != std::string_view::npos; at = text.find(word, at + 1)) {
    const bool starts = at == 0 || !word_char(text[at - 1]) || !word_char(word.front());
    const std::size_t end = at + word.size();
    const bool ends = end == text.size() || !word_char(text[end]) || !word_char(word.back());
    if (starts && ends) return true;
  }
  return false;
}

}  // namespace

std::vector<std::size_t> find_help(const std::vector<HelpEntry>& entries, std::string_view word) {
  std::vector<std::size_t> found;
  if (word.empty()) return found;
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (entries[i].name == word) found.push_back(i);
  if (!found.empty()) return found;
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (has_whole_word(entries[i].name, word) || has_whole_word(entries[i].text, word))
      found.push_back(i);
  if (!found.empty()) return found;
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (entries[i].name.find(word) != std::string::npos ||
        entries[i].text.find(word) != std::string::npos)
      found.push_back(i);
  return found;
}

}  // namespace stride::console
