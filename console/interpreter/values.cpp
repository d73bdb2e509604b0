#include "console/interpreter/values.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "robot/core/error.hpp"
#include "robot/model/physical_limits.hpp"

namespace stride::console {

namespace {
bool read_double(std::string_view w, double& out) {
  if (w.empty()) return false;
  if (w.front() == '+') w.remove_prefix(1);
  const auto r = std::from_chars(w.data(), w.data() + w.size(), out);
  return r.ec == std::errc() && r.ptr == w.data() + w.size() && std::isfinite(out);
}
// Booleans compare as numbers so `expect robot.fell == 0` and `== false` both work.
bool as_number(const std::string& w, double& out) {
  if (w == "true") return out = 1, true;
  if (w == "false") return out = 0, true;
  return read_double(w, out);
}
}  // namespace

bool is_number(std::string_view word) {
  double v;
  return read_double(word, v);
}

double parse_number(std::string_view word, const std::string& what) {
  double v;
  if (!read_double(word, v))
    throw Error(what + ": expected a number, got '" + std::string(word) + "'");
  return v;
}

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

long long parse_integer(std::string_view word, const std::string& what, long long low,
                        long long high) {
  long long v = 0;
  const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
  if (word.empty() || r.ec != std::errc() || r.ptr != word.data() + word.size())
    throw Error(what + ": expected an integer, got '" + std::string(word) + "'");
  if (v < low || v > high)
    throw Error(what + ": " + std::to_string(v) + " is outside [" + std::to_string(low) + ", " +
                std::to_string(high) + "]");
  return v;
}

bool parse_on_off(std::string_view word, const std::string& what) {
  if (word == "on") return true;
  if (word == "off") return false;
  throw Error(what + ": expected on or off, got '" + std::string(word) + "'");
}

Op parse_op(std::string_view w) {
  if (w == "==") return Op::Equal;
  if (w == "!=") return Op::NotEqual;
  if (w == "<") return Op::Less;
  if (w == "<=") return Op::LessEqual;
  if (w == ">") return Op::Greater;
  if (w == ">=") return Op::GreaterEqual;
  if (w == "~=") return Op::Near;
  throw Error("expected an operator (== != < <= > >= ~=), got '" + std::string(w) + "'");
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
  throw Error("'" + actual + "' " + std::string(op_text(op)) + " '" + expected +
              "': only == and != compare words");
}

}  // namespace stride::console
