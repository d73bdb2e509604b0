#include "robot/core/number_text.hpp"

#include <charconv>
#include <cmath>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"

namespace stride {
namespace {

bool read_double(std::string_view w, double& out) {
  if (w.empty()) return false;
  if (w.front() == '+') w.remove_prefix(1);
  const auto r = std::from_chars(w.data(), w.data() + w.size(), out);
  return r.ec == std::errc() && r.ptr == w.data() + w.size() && std::isfinite(out);
}

}  // namespace

bool is_number(std::string_view word) {
  double v;
  return read_double(word, v);
}

double parse_number(std::string_view word, const std::string& what) {
  double v;
  if (!read_double(word, v)) throw Error(what + ": expected a number, got " + quote(word));
  return v;
}

long long parse_integer(std::string_view word, const std::string& what, long long low,
                        long long high) {
  long long v = 0;
  const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
  if (word.empty() || r.ec != std::errc() || r.ptr != word.data() + word.size())
    throw Error(what + ": expected an integer, got " + quote(word));
  if (v < low || v > high)
    throw Error(what + ": " + std::to_string(v) + " is outside [" + std::to_string(low) + ", " +
                std::to_string(high) + "]");
  return v;
}

std::uint64_t parse_unsigned(std::string_view word, const std::string& what) {
  std::uint64_t v = 0;
  const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
  if (word.empty() || r.ec != std::errc() || r.ptr != word.data() + word.size())
    throw Error(what + ": expected a non-negative integer, got " + quote(word));
  return v;
}

}  // namespace stride
