#include "robot/core/quote.hpp"

#include "robot/core/one_line.hpp"
#include "robot/core/utf8.hpp"

#include <algorithm>
#include <cstdio>

namespace stride {
namespace {

constexpr std::size_t kQuoteLimit = 80;        // characters quoted whole
constexpr std::size_t kHead = 56, kTail = 16;  // kept of a longer text

// Control characters and bytes that are not UTF-8 are escaped: the text stays valid UTF-8.
void append_escaped(std::string& out, std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const auto u = static_cast<unsigned char>(c);
    const std::size_t n = u < 0x80 ? 1 : utf8_char_length(text, i);
    if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (u < 0x20 || u == 0x7f || n == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    } else
      out.append(text.substr(i, n));
    i += n == 0 ? 1 : n;
  }
}

// Cuts fall on character boundaries: never inside a UTF-8 sequence.
bool continuation(char c) {
  return (static_cast<unsigned char>(c) & 0xc0) == 0x80;
}

}  // namespace

std::string quote(std::string_view text) {
  std::string out = "'";
  if (text.size() <= kQuoteLimit) {
    append_escaped(out, text);
    return out + "'";
  }
  std::size_t head = kHead, tail = text.size() - kTail;
  while (head > 0 && continuation(text[head])) --head;
  while (tail < text.size() && continuation(text[tail])) ++tail;
  append_escaped(out, text.substr(0, head));
  out += "...";
  append_escaped(out, text.substr(tail));
  return out + "' (" + std::to_string(text.size()) + " characters)";
}

std::string one_line(std::string_view text, std::size_t max) {
  std::string out;
  std::size_t cut = std::min(max, text.size());
  while (cut > 0 && cut < text.size() && continuation(text[cut])) --cut;
  append_escaped(out, text.substr(0, cut));
  return text.size() > max ? out + "..." : out;
}

}  // namespace stride
