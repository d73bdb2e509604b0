#pragma once
// Enumerator names through a type's EnumNames (reflect.hpp): the one way an enum is printed or
// read by name, instead of hand-written switches.
#include <optional>
#include <string_view>

#include "robot/framework/reflect.hpp"

namespace stride {

// An enumerator's name from its EnumNames; "?" for a value outside the list.
template <NamedEnum E>
constexpr std::string_view enum_name(E e) {
  const auto i = static_cast<std::size_t>(e);
  return i < EnumNames<E>::names.size() ? EnumNames<E>::names[i] : std::string_view("?");
}

// The enumerator of that name, if there is one.
template <NamedEnum E>
constexpr std::optional<E> enum_from_name(std::string_view name) {
  for (std::size_t i = 0; i < EnumNames<E>::names.size(); ++i)
    if (EnumNames<E>::names[i] == name) return static_cast<E>(i);
  return std::nullopt;
}

}  // namespace stride
