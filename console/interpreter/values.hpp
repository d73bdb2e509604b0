#pragma once
// Strict readers for command arguments and the comparison used by `expect` and `wait until`.
#include <string>
#include <string_view>

#include "robot/core/number_text.hpp"

namespace stride::console {

// Numbers through the project's one reader (robot/core/number_text.hpp).
using stride::is_number;
using stride::parse_integer;
using stride::parse_number;
// A number with |v| <= bound: "fx: 1e+308 N outside [-1e+07, 1e+07]" otherwise.
double parse_bounded(std::string_view word, const std::string& what, double bound,
                     const std::string& unit);
// A duration in [0, limits::kMaxDuration] seconds.
double parse_seconds(std::string_view word, const std::string& what);
bool parse_on_off(std::string_view word, const std::string& what);

enum class Op { Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual, Near };
Op parse_op(std::string_view word);  // == != < <= > >= ~=
std::string_view op_text(Op op);

// Numbers compare numerically (== and ~= within `tolerance`); other words only by == and !=.
bool compare(const std::string& actual, Op op, const std::string& expected, double tolerance);

}  // namespace stride::console
