#pragma once
// Field lists: a representation or parameter struct names its fields once, and every generic
// operation (text, binary, CSV, type description) is derived from that list.
//
//   struct Foo {
//     double knee = 0;  Eigen::Vector2d cop = Eigen::Vector2d::Zero();
//     static constexpr std::string_view kTypeName = "Foo";
//     static constexpr auto fields() {
//       return std::make_tuple(stride::field("knee", &Foo::knee, "rad", {-0.09, 2.11}),
//                              stride::field("cop", &Foo::cop, "m"));
//     }
//   };
//
// Types that cannot carry a member (e.g. robot/hal structs) specialise stride::Reflect<T> instead.
#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>

namespace stride {

// Inclusive bounds a text update must respect (checked per element for arrays).
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

template <class Owner, class Member>
struct Field {
  std::string_view name;
  Member Owner::*member;
  std::string_view unit;
  std::optional<Range> range;
  std::span<const std::string_view> element_names{};  // an array's elements by name

  // The same field with its array elements named, e.g. by joint: text shows
  // [HeadYaw=0, ...] and paths may say position[LAnklePitch].
  constexpr Field named(std::span<const std::string_view> names) const {
    Field f = *this;
    f.element_names = names;
    return f;
  }
};

template <class Owner, class Member>
constexpr Field<Owner, Member> field(std::string_view name, Member Owner::*member,
                                     std::string_view unit = {},
                                     std::optional<Range> range = std::nullopt) {
  return {name, member, unit, range};
}

// Default: the type lists its own fields; specialise for types you do not own.
template <class T>
struct Reflect {
  static constexpr std::string_view type_name() { return T::kTypeName; }
  static constexpr auto fields() { return T::fields(); }
};

template <class T>
concept Reflected = requires {
  { Reflect<T>::type_name() } -> std::convertible_to<std::string_view>;
  Reflect<T>::fields();
};

// Enums are printed and parsed by name: specialise with the type's name and the names of 0..N-1.
//   template <> struct EnumNames<Mode> {
//     static constexpr std::string_view type_name = "Mode";
//     static constexpr std::array<std::string_view, 2> names{"A", "B"};
//   };
template <class E>
struct EnumNames;

template <class E>
concept NamedEnum = std::is_enum_v<E> && requires {
  EnumNames<E>::names;
  EnumNames<E>::type_name;
};

template <class T, class F>
constexpr void for_each_field(F&& f) {
  std::apply([&](const auto&... field) { (f(field), ...); }, Reflect<T>::fields());
}

}  // namespace stride
