#include "robot/core/utf8.hpp"

namespace stride {

namespace {
bool in(unsigned char c, unsigned lo, unsigned hi) {
  return c >= lo && c <= hi;
}
}  // namespace

std::size_t utf8_char_length(std::string_view text, std::size_t at) {
  auto byte = [&](std::size_t i) {
    return at + i < text.size() ? static_cast<unsigned char>(text[at + i]) : 0u;
  };
  const unsigned char c = byte(0);
  if (at >= text.size()) return 0;
  if (c < 0x80) return 1;
  // The second byte's range depends on the first (RFC 3629, section 4); the rest are 80-BF.
  unsigned lo = 0x80, hi = 0xbf;
  std::size_t n = 0;
  if (in(c, 0xc2, 0xdf)) {
    n = 2;
  } else if (in(c, 0xe0, 0xef)) {
    n = 3;
    if (c == 0xe0) lo = 0xa0;
    if (c == 0xed) hi = 0x9f;
  } else if (in(c, 0xf0, 0xf4)) {
    n = 4;
    if (c == 0xf0) lo = 0x90;
    if (c == 0xf4) hi = 0x8f;
  } else {
    return 0;
  }
  if (!in(static_cast<unsigned char>(byte(1)), lo, hi)) return 0;
  for (std::size_t i = 2; i < n; ++i)
    if (!in(static_cast<unsigned char>(byte(i)), 0x80, 0xbf)) return 0;
  return n;
}

bool valid_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_char_length(text, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string utf8_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_char_length(text, i);
    if (n > 0) {
      out.append(text.substr(i, n));
      i += n;
      continue;
    }
    static constexpr char kHex[] = "0123456789abcdef";
    const auto u = static_cast<unsigned char>(text[i++]);
    out += "\\x";
    out += kHex[u >> 4];
    out += kHex[u & 15];
  }
  return out;
}

}  // namespace stride
