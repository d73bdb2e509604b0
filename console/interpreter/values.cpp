#include "console/interpreter/values.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "robot/core/error.hpp"
#include "robot/core/physical_limits.hpp"
#include "robot/core/quote.hpp"

namespace stride::console {

namespace {
// Booleans compare as numbers so `expect robot.fell == 0` and `== false` both work.
bool as_number(const std::string& w, double& out) {
  if (w == "true") return out = 1, true;
  if (w == "false") return out = 0, true;
  if (!is_number(w)) return false;
  out = parse_number(w, "");
  return true;
}
}  // namespace

double parse_bounded(std::string_view word, const std::string& what, double bound,
                     const std::string& unit) {
  const double v = parse_number(word, what);
  if (std::abs(v) > bound) {
    std::ostringstream msg;
    msg << what << ": " << v << " " << unit << " outside [" << -bound << ", " << bound << "]";
    throw Error(msg.str());
  }
  return v;
}

double parse_seconds(std::string_view word, const std::string& what) {
  const double v = parse_number(word, what);
  if (const std::string p = limits::duration_problem(v); !p.empty()) throw Error(what + ": " + p);
  return v;
}

bool parse_on_off(std::string_view word, const std::string& what) {
  if (word == "on") return true;
  if (word == "off") return false;
  throw Error(what + ": expected on or off, got " + quote(word));
}

Op parse_op(std::string_view w) {
  if (w == "==") return Op::Equal;
  if (w == "!=") return Op::NotEqual;
  if (w == "<") return Op::Less;
  if (w == "<=") return Op::LessEqual;
  if (w == ">") return Op::Greater;
  if (w == ">=") return Op::GreaterEqual;
  if (w == "~=") return Op::Near;
  throw Error("expected an operator (== != < <= > >= ~=), got " + quote(w));
}

std::string_view op_text(Op op) {
  switch (op) {
    case Op::Equal:
      return "==";
    case Op::NotEqual:
      return "!=";
    case Op::Less:
      return "<";
    case Op::LessEqual:
      return "<=";
    case Op::Greater:
      return ">";
    case Op::GreaterEqual:
      return ">=";
    case Op::Near:
      return "~=";
  }
  return "?";
}

bool compare(const std::string& actual, Op op, const std::string& expected, double tolerance) {
  double a = 0, e = 0;
  if (as_number(actual, a) && as_number(expected, e)) {
    switch (op) {
      case Op::Equal:
        return std::abs(a - e) <= tolerance;
      case Op::NotEqual:
        return std::abs(a - e) > tolerance;
      case Op::Less:
        return a < e;
      case Op::LessEqual:
        return a <= e;
      case Op::Greater:
        return a > e;
      case Op::GreaterEqual:
        return a >= e;
      case Op::Near:
        return std::abs(a - e) <= tolerance;
    }
  }
  if (op == Op::Equal) return actual == expected;
  if (op == Op::NotEqual) return actual != expected;
  throw Error(quote(actual) + " " + std::string(op_text(op)) + " '" + expected +
              "': only == and != compare words");
}

}  // namespace stride::console
