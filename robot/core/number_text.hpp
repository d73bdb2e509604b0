#pragma once
// Numbers as people type them and as error messages show them. The one reader of numbers typed
// by people (command-line flags, console arguments, --set values): the whole word, finite, errors
// as "<what>: expected a number, got '<word>'".
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>

namespace stride {

// A finite number, the whole word (a leading '+' allowed); else stride::Error.
double parse_number(std::string_view word, const std::string& what);
// An integer in [low, high]; else stride::Error naming the range.
long long parse_integer(std::string_view word, const std::string& what, long long low,
                        long long high);
// A non-negative integer up to 2^64 - 1 (seeds).
std::uint64_t parse_unsigned(std::string_view word, const std::string& what);
bool is_number(std::string_view word);

// A number as an error message shows it: six significant digits, "1e+300", "0.01", "100000".
inline std::string short_number(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

}  // namespace stride
