#include "robot/core/xml_element.hpp"

#include <charconv>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/quote.hpp"

namespace stride {

void XmlElement::fail(const std::string& message) const {
  throw error_at(file_, line(), "<" + std::string(name()) + ">: " + message);
}

void XmlElement::fail_attr(const char* attr, const std::string& message) const {
  fail("attribute " + quote(attr) + ": " + message);
}

void XmlElement::allow_only(std::span<const std::string_view> allowed) const {
  for (const tinyxml2::XMLAttribute* a = e_->FirstAttribute(); a; a = a->Next()) {
    bool ok = false;
    for (auto n : allowed) ok = ok || n == a->Name();
    if (!ok) {
      std::string list;
      for (auto n : allowed) list += (list.empty() ? "" : ", ") + std::string(n);
      fail("unknown attribute " + quote(std::string(a->Name())) + " (expected " +
           (list.empty() ? std::string("none") : list) + ")");
    }
  }
}

std::string XmlElement::text(const char* attr) const {
  const char* v = e_->Attribute(attr);
  if (!v) fail("missing attribute " + quote(attr));
  return v;
}

std::string XmlElement::text_or(const char* attr, const std::string& fallback) const {
  const char* v = e_->Attribute(attr);
  return v ? std::string(v) : fallback;
}

double XmlElement::number(const char* attr, Dimension d) const {
  const std::string t = text(attr);
  try {
    return parse_quantity(t, d);
  } catch (const std::invalid_argument& ex) {
    fail_attr(attr, ex.what());
  }
}

double XmlElement::number_or(const char* attr, double fallback, Dimension d) const {
  return has(attr) ? number(attr, d) : fallback;
}

int XmlElement::integer_or(const char* attr, int fallback, int min, int max) const {
  if (!has(attr)) return fallback;
  const std::string t = text(attr);
  int v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size() || v < min || v > max)
    fail_attr(attr, quote(t) + " (expected an integer in [" + std::to_string(min) + ", " +
                        std::to_string(max) + "])");
  return v;
}

std::uint64_t XmlElement::seed_or(const char* attr, std::uint64_t fallback) const {
  if (!has(attr)) return fallback;
  const std::string t = text(attr);
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size())
    fail_attr(attr, quote(t) + " (expected a non-negative integer seed)");
  return v;
}

bool XmlElement::boolean_or(const char* attr, bool fallback) const {
  if (!has(attr)) return fallback;
  const std::string t = text(attr);
  if (t == "true" || t == "on" || t == "1") return true;
  if (t == "false" || t == "off" || t == "0") return false;
  fail_attr(attr, quote(t) + " (expected true/false or on/off)");
}

namespace {
std::vector<std::string> split_words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}
}  // namespace

Eigen::Vector3d XmlElement::vector3_or(const char* attr, const Eigen::Vector3d& fallback,
                                       Dimension d) const {
  if (!has(attr)) return fallback;
  const auto words = split_words(text(attr));
  if (words.size() != 3)
    fail_attr(attr, quote(text(attr)) + " (expected three values, each " +
                        std::string(dimension_name(d)) + ")");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) try {
      v[i] = parse_quantity(words[i], d);
    } catch (const std::invalid_argument& ex) {
      fail_attr(attr, ex.what());
    }
  return v;
}

Eigen::Vector2d XmlElement::vector2_or(const char* attr, const Eigen::Vector2d& fallback,
                                       Dimension d) const {
  if (!has(attr)) return fallback;
  const auto words = split_words(text(attr));
  if (words.size() != 2)
    fail_attr(attr, quote(text(attr)) + " (expected two values, each " +
                        std::string(dimension_name(d)) + ")");
  Eigen::Vector2d v;
  for (int i = 0; i < 2; ++i) try {
      v[i] = parse_quantity(words[i], d);
    } catch (const std::invalid_argument& ex) {
      fail_attr(attr, ex.what());
    }
  return v;
}

namespace {
const char* si_unit(Dimension d) {
  switch (d) {
    case Dimension::Length:
      return " m";
    case Dimension::Angle:
      return " rad";
    case Dimension::Mass:
      return " kg";
    case Dimension::Time:
      return " s";
    case Dimension::Force:
      return " N";
    case Dimension::Frequency:
      return " Hz";
    case Dimension::None:
      break;
  }
  return "";
}
}  // namespace

void XmlElement::check_within(const char* attr, double v, double lo, double hi, Dimension d) const {
  if (!(v >= lo && v <= hi))
    fail_attr(attr, short_number(v) + si_unit(d) + " outside [" + short_number(lo) + ", " +
                        short_number(hi) + "]");
}

double XmlElement::number_within(const char* attr, double fallback, double lo, double hi,
                                 Dimension d) const {
  const double v = number_or(attr, fallback, d);
  if (has(attr)) check_within(attr, v, lo, hi, d);
  return v;
}

Eigen::Vector3d XmlElement::vector3_within(const char* attr, const Eigen::Vector3d& fallback,
                                           double bound, Dimension d) const {
  const Eigen::Vector3d v = vector3_or(attr, fallback, d);
  if (has(attr))
    for (int i = 0; i < 3; ++i) check_within(attr, v[i], -bound, bound, d);
  return v;
}

Eigen::Vector2d XmlElement::vector2_within(const char* attr, const Eigen::Vector2d& fallback,
                                           double bound, Dimension d) const {
  const Eigen::Vector2d v = vector2_or(attr, fallback, d);
  if (has(attr))
    for (int i = 0; i < 2; ++i) check_within(attr, v[i], -bound, bound, d);
  return v;
}

int XmlElement::choice_or(const char* attr, std::initializer_list<std::string_view> choices,
                          int fallback) const {
  if (!has(attr)) return fallback;
  const std::string t = text(attr);
  int i = 0;
  std::string list;
  for (auto c : choices) {
    if (c == t) return i;
    list += (i++ ? ", " : "") + std::string(c);
  }
  fail_attr(attr, quote(t) + " (expected one of " + list + ")");
}

}  // namespace stride
