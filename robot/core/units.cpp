#include "robot/core/units.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"

namespace stride {
namespace {

struct Unit {
  std::string_view name;
  Dimension dim;
  double factor;
};

constexpr Unit kUnits[] = {
    {"m", Dimension::Length, 1.0},
    {"cm", Dimension::Length, 0.01},
    {"mm", Dimension::Length, 0.001},
    {"rad", Dimension::Angle, 1.0},
    {"deg", Dimension::Angle, std::numbers::pi / 180.0},
    {"kg", Dimension::Mass, 1.0},
    {"g", Dimension::Mass, 0.001},
    {"s", Dimension::Time, 1.0},
    {"ms", Dimension::Time, 0.001},
    {"N", Dimension::Force, 1.0},
    {"Hz", Dimension::Frequency, 1.0},
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

std::string_view dimension_name(Dimension d) {
  switch (d) {
    case Dimension::None:
      return "a number";
    case Dimension::Length:
      return "a length (m, cm, mm)";
    case Dimension::Angle:
      return "an angle (rad, deg)";
    case Dimension::Mass:
      return "a mass (kg, g)";
    case Dimension::Time:
      return "a time (s, ms)";
    case Dimension::Force:
      return "a force (N)";
    case Dimension::Frequency:
      return "a frequency (Hz)";
  }
  return "a number";
}

double parse_quantity(std::string_view text, Dimension d) {
  const std::string_view s = trim(text);
  double value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end == s.data())
    throw std::invalid_argument(quote(text) + " is not " + std::string(dimension_name(d)));
  if (!std::isfinite(value))
    throw std::invalid_argument(quote(text) + " is not finite (expected " +
                                std::string(dimension_name(d)) + ")");
  const std::string_view unit = trim(s.substr(end - s.data()));
  if (unit.empty()) return value;
  for (const Unit& u : kUnits)
    if (u.name == unit) {
      if (u.dim != d)
        throw std::invalid_argument("unit " + quote(unit) + " in " + quote(text) + " (expected " +
                                    std::string(dimension_name(d)) + ")");
      return value * u.factor;
    }
  throw std::invalid_argument("unknown unit " + quote(unit) + " in " + quote(text) + " (expected " +
                              std::string(dimension_name(d)) + ")");
}

}  // namespace stride
