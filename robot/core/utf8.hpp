#pragma once
// UTF-8 as RFC 3629 defines it (no overlong forms, no surrogates, nothing above U+10FFFF): text
// from a peer is checked before it is used, and errors escape what is not UTF-8 (quote.cpp).
#include <cstddef>
#include <string>
#include <string_view>

namespace stride {

// Bytes of the well-formed character starting at text[at] (1-4), or 0 if none starts there.
std::size_t utf8_char_length(std::string_view text, std::size_t at);
bool valid_utf8(std::string_view text);
// `text` with every byte that is not part of a well-formed character written as \xNN (the rest,
// control characters too, unchanged): what is sent as a string is always UTF-8.
std::string utf8_escaped(std::string_view text);

}  // namespace stride
