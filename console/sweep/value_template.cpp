#include "console/sweep/value_template.hpp"

#include <charconv>
#include <cstdio>
#include <regex>

#include "console/sweep/expression.hpp"
#include "console/sweep/run_plan.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

std::string printed(const Cell& v, const std::string& conversion, const std::string& where) {
  if (conversion.empty()) {
    if (const double* d = std::get_if<double>(&v)) return number_text(*d);
    return std::get<std::string>(v);
  }
  static const std::regex ok("[-+ #0]*[0-9]{0,2}(\\.[0-9]{1,2})?[eEfFgG]");
  if (!std::regex_match(conversion, ok))
    throw Error(where + ": conversion '" + conversion +
                "': expected a printf number format such as g, .3f or 8.2e");
  const double* d = std::get_if<double>(&v);
  if (!d) throw Error(where + ": a text cannot be printed with '" + conversion + "'");
  char buf[64];
  std::snprintf(buf, sizeof buf, ("%" + conversion).c_str(), *d);
  return buf;
}

}  // namespace

std::string expand_template(const std::string& text, const std::string& name,
                            const std::string& level_text) {
  double number = 0;
  const auto r = std::from_chars(level_text.data(), level_text.data() + level_text.size(), number);
  const bool numeric =
      !level_text.empty() && r.ec == std::errc() && r.ptr == level_text.data() + level_text.size();
  const std::vector<Cell> slots{numeric ? Cell(number) : Cell(level_text)};
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t open = text.find('{', i);
    if (open == std::string::npos) {
      out += text.substr(i);
      break;
    }
    out += text.substr(i, open - i);
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) throw Error("'" + text + "': '{' without '}'");
    std::string inner = text.substr(open + 1, close - open - 1);
    std::string conversion;
    if (const std::size_t colon = inner.rfind(':'); colon != std::string::npos)
      conversion = inner.substr(colon + 1), inner = inner.substr(0, colon);
    const std::string where = "'" + text + "'";
    if (inner.empty()) {
      out += conversion.empty() ? level_text : printed(slots[0], conversion, where);
    } else {
      const Expression e(inner, [&](std::string_view n) -> int {
        if (n != name)
          throw Error("unknown name '" + std::string(n) + "' (a level's value is '" + name + "')");
        return 0;
      });
      out += printed(e.evaluate(slots), conversion, where);
    }
    i = close + 1;
  }
  return out;
}

}  // namespace stride::sweep
