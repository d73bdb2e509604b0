#pragma once
// Strict reading of one XML element: every attribute is declared by the reader, any other one is
// an error, and every error says file:line and what was expected.
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <tinyxml2.h>
#include <Eigen/Core>

#include "robot/core/units.hpp"

namespace stride {

class XmlElement {
 public:
  XmlElement(const tinyxml2::XMLElement* e, const std::string& file) : e_(e), file_(file) {}

  std::string_view name() const { return e_->Name(); }
  int line() const { return e_->GetLineNum(); }
  const std::string& file() const { return file_; }
  const tinyxml2::XMLElement* raw() const { return e_; }

  // Throws unless every attribute is in `allowed`.
  void allow_only(std::initializer_list<std::string_view> allowed) const {
    allow_only(std::span<const std::string_view>(allowed.begin(), allowed.size()));
  }
  void allow_only(std::span<const std::string_view> allowed) const;

  bool has(const char* attr) const { return e_->Attribute(attr) != nullptr; }
  std::string text(const char* attr) const;  // required
  std::string text_or(const char* attr, const std::string& fallback) const;
  double number(const char* attr, Dimension d = Dimension::None) const;  // required
  double number_or(const char* attr, double fallback, Dimension d = Dimension::None) const;
  int integer_or(const char* attr, int fallback, int min, int max) const;
  std::uint64_t seed_or(const char* attr, std::uint64_t fallback) const;
  bool boolean_or(const char* attr, bool fallback) const;
  Eigen::Vector3d vector3_or(const char* attr, const Eigen::Vector3d& fallback,
                             Dimension d = Dimension::None) const;
  Eigen::Vector2d vector2_or(const char* attr, const Eigen::Vector2d& fallback,
                             Dimension d = Dimension::None) const;
  // The same, each value also within [lo, hi] (in SI units after conversion); a value outside
  // is an error naming it and the range, e.g. "attribute 'xyz': 1e+300 m outside [-1e4, 1e4]".
  double number_within(const char* attr, double fallback, double lo, double hi,
                       Dimension d = Dimension::None) const;
  Eigen::Vector3d vector3_within(const char* attr, const Eigen::Vector3d& fallback, double bound,
                                 Dimension d = Dimension::None) const;
  Eigen::Vector2d vector2_within(const char* attr, const Eigen::Vector2d& fallback, double bound,
                                 Dimension d = Dimension::None) const;
  // Fails unless lo <= v <= hi, naming `attr`, v and the range.
  void check_within(const char* attr, double v, double lo, double hi, Dimension d) const;
  // One of `choices`, returned as its index.
  int choice_or(const char* attr, std::initializer_list<std::string_view> choices,
                int fallback) const;

  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void fail_attr(const char* attr, const std::string& message) const;

 private:
  const tinyxml2::XMLElement* e_;
  const std::string& file_;
};

}  // namespace stride
