#pragma once
// The one JSON writer: run reports and every command's --json output. Stride writes JSON but
// never reads it, so a streaming writer (no dependency for the robot binary) is all it needs.
// Numbers are the shortest text that reads back to the same double; non-finite ones are null;
// bytes that are not UTF-8 become U+FFFD, so the output is always valid JSON.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "robot/core/utf8.hpp"

namespace stride {

class JsonWriter {
 public:
  // Compact: {"a":1,"b":[2,3]} (files). Spaced: {"a": 1, "b": [2, 3]} (one line for people).
  enum class Style { Compact, Spaced };
  explicit JsonWriter(Style style = Style::Compact) : spaced_(style == Style::Spaced) {}

  JsonWriter& begin_object() {
    value_prefix();
    out_ += '{';
    first_.push_back(true);
    return *this;
  }
  JsonWriter& end_object() {
    out_ += '}';
    first_.pop_back();
    return *this;
  }
  JsonWriter& begin_array() {
    value_prefix();
    out_ += '[';
    first_.push_back(true);
    return *this;
  }
  JsonWriter& end_array() {
    out_ += ']';
    first_.pop_back();
    return *this;
  }
  JsonWriter& key(std::string_view k) {
    comma();
    string_literal(k);
    out_ += spaced_ ? ": " : ":";
    after_key_ = true;
    return *this;
  }
  JsonWriter& value(double v) {
    value_prefix();
    if (!std::isfinite(v)) {
      out_ += "null";
    } else {
      char buf[32];
      const auto r = std::to_chars(buf, buf + sizeof buf, v);
      out_.append(buf, r.ptr);
    }
    return *this;
  }
  JsonWriter& value(long long v) {
    value_prefix();
    out_ += std::to_string(v);
    return *this;
  }
  JsonWriter& value(int v) { return value(static_cast<long long>(v)); }
  JsonWriter& value(std::uint64_t v) {
    value_prefix();
    out_ += std::to_string(v);
    return *this;
  }
  JsonWriter& null() {
    value_prefix();
    out_ += "null";
    return *this;
  }
  // An array of numbers in one call.
  template <class Range>
  JsonWriter& numbers(const Range& values) {
    begin_array();
    for (const double v : values) value(v);
    return end_array();
  }
  JsonWriter& value(bool v) {
    value_prefix();
    out_ += v ? "true" : "false";
    return *this;
  }
  JsonWriter& value(std::string_view s) {
    value_prefix();
    string_literal(s);
    return *this;
  }
  JsonWriter& value(const char* s) { return value(std::string_view(s)); }
  template <class T>
  JsonWriter& field(std::string_view k, const T& v) {
    key(k);
    return value(v);
  }
  const std::string& str() const { return out_; }

 private:
  void comma() {
    if (!first_.empty()) {
      if (!first_.back()) out_ += spaced_ ? ", " : ",";
      first_.back() = false;
    }
  }
  void value_prefix() {
    if (after_key_)
      after_key_ = false;
    else
      comma();
  }
  void string_literal(std::string_view s) {
    out_ += '"';
    for (std::size_t i = 0; i < s.size(); ++i) {
      const char c = s[i];
      switch (c) {
        case '"':
          out_ += "\\\"";
          break;
        case '\\':
          out_ += "\\\\";
          break;
        case '\n':
          out_ += "\\n";
          break;
        case '\t':
          out_ += "\\t";
          break;
        default:
          if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out_ += buf;
          } else if (static_cast<unsigned char>(c) < 0x80) {
            out_ += c;
          } else if (const std::size_t n = utf8_char_length(s, i); n > 0) {
            out_.append(s.substr(i, n));
            i += n - 1;
          } else {
            out_ += "\xef\xbf\xbd";  // U+FFFD for a byte that is not UTF-8: the JSON stays valid
          }
      }
    }
    out_ += '"';
  }
  std::string out_;
  std::vector<bool> first_;
  bool after_key_ = false;
  bool spaced_ = false;
};

}  // namespace stride
