#include "simulator/render/body_side.hpp"

#include <cctype>

namespace stride::render {
namespace {

bool starts_with_word(std::string_view name, std::string_view word) {
  if (name.size() < word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(name[i])) != word[i]) return false;
  return true;
}

// "L" or "R" as a prefix: followed by a capital ("LThigh") or a separator ("l_hip", "r.foot").
bool side_letter(std::string_view name, char letter) {
  if (name.size() < 2 || std::tolower(static_cast<unsigned char>(name[0])) != letter) return false;
  const char next = name[1];
  return std::isupper(static_cast<unsigned char>(next)) || next == '_' || next == '.' ||
         next == '-';
}

}  // namespace

BodySide side_of_link(std::string_view name) {
  if (starts_with_word(name, "left") || side_letter(name, 'l')) return BodySide::Left;
  if (starts_with_word(name, "right") || side_letter(name, 'r')) return BodySide::Right;
  return BodySide::Centre;
}

}  // namespace stride::render
