#pragma once
// Typed text form of reflected values, derived from the binary form and the type description.
#include <string>
#include <string_view>

#include "robot/framework/binary.hpp"
#include "robot/framework/value.hpp"

namespace stride {

template <class T>
Value to_value(const T& v) {
  const auto bytes = to_binary(v);
  ByteReader r(bytes);
  return read_value(*describe<T>(), r);
}

template <class T>
void from_value(T& v, const Value& value) {
  std::string bytes;
  ByteWriter w(bytes);
  write_value(*describe<T>(), value, w);
  from_binary(v, bytes);
}

// e.g. {time=0.01, frame=3, period=0.01}
template <class T>
std::string to_text(const T& v) {
  return print_value(*describe<T>(), to_value(v));
}

// Whole value "{...}" or partial "position[3]=0.5 cop.x=0.01". All or nothing; the error names
// the field (prefixed by `root`, default the type's name) and what was expected.
template <class T>
void update_from_text(T& v, std::string_view text, std::string_view root = {}) {
  const auto& d = *describe<T>();
  Value value = to_value(v);
  update_value(d, value, text, root.empty() ? std::string_view(d.name) : root);
  from_value(v, value);
}

// A value of T built from default-constructed T and `text`.
template <class T>
T from_text(std::string_view text) {
  T v{};
  update_from_text(v, text);
  return v;
}

}  // namespace stride
