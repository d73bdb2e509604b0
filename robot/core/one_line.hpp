#pragma once
// Text from a peer or a file quoted in an error without quotes around it: control characters
// escaped as quote() escapes them (\n, \t, \xNN) and cut to `max` characters with "..." after, so
// an error stays one printable line whatever was sent. Implemented beside quote() in quote.cpp.
#include <cstddef>
#include <string>
#include <string_view>

namespace stride {

std::string one_line(std::string_view text, std::size_t max = 80);

}  // namespace stride
