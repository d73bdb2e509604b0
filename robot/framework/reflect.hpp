#pragma once
// Field lists: a representation or parameter struct names each field once, where it declares it,
// and every generic operation (text, binary, CSV, type description) is derived from that list.
//
//   struct Foo {
//     STRIDE_FIELDS(Foo);
//     STRIDE_FIELD(double, knee, "rad", Range{-0.09, 2.11}) = 0;
//     STRIDE_FIELD(Eigen::Vector2d, cop, "m") = Eigen::Vector2d::Zero();
//     STRIDE_FIELD((std::array<double, 26>), position, "rad", {}, hal::kJointNames){};
//     static constexpr std::string_view kTypeName = "Foo";
//   };
//
// STRIDE_FIELD(type, name, unit, range, element names) declares the member and its entry: the
// arguments after the name are those of field() below (a type with a comma goes in parentheses),
// and the initialiser follows the macro. Fields are listed in declaration order, one per line.
// Types that cannot carry a member (e.g. robot/hal structs) specialise stride::Reflect<T> instead.
#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

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
                                     std::optional<Range> range = std::nullopt,
                                     std::span<const std::string_view> element_names = {}) {
  return {name, member, unit, range, element_names};
}

namespace field_list {

// A field's slot: its line below STRIDE_FIELDS, the same in every translation unit.
template <int Line>
struct Slot {};
inline constexpr int kMaxLines = 128;  // how far below STRIDE_FIELDS fields are looked for

template <class T, int Line>
constexpr auto entry_at() {
  if constexpr (requires { T::stride_field(Slot<Line>{}); })
    return std::make_tuple(T::stride_field(Slot<Line>{}));
  else
    return std::tuple<>{};
}

template <class T, int... Lines>
constexpr auto entries(std::integer_sequence<int, Lines...>) {
  return std::tuple_cat(entry_at<T, Lines>()...);
}

}  // namespace field_list

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

// Opens a struct's field list: fields() returns the STRIDE_FIELDs declared below, in order.
#define STRIDE_FIELDS(TYPE)                                                  \
  using StrideFieldOwner = TYPE;                                             \
  static constexpr int stride_fields_line = __LINE__;                        \
  template <class Owner = StrideFieldOwner>                                  \
  static constexpr auto fields() {                                           \
    return ::stride::field_list::entries<Owner>(                             \
        std::make_integer_sequence<int, ::stride::field_list::kMaxLines>{}); \
  }                                                                          \
  static_assert(true)

// Declares a member and its field entry; the initialiser, if any, follows the macro.
#define STRIDE_FIELD(TYPE, NAME, ...)                                                             \
  static_assert(__LINE__ - stride_fields_line < ::stride::field_list::kMaxLines,                  \
                "STRIDE_FIELD " #NAME ": too far below STRIDE_FIELDS (raise kMaxLines)");         \
  static constexpr auto stride_field(::stride::field_list::Slot<__LINE__ - stride_fields_line>) { \
    return ::stride::field(#NAME, &StrideFieldOwner::NAME __VA_OPT__(, ) __VA_ARGS__);            \
  }                                                                                               \
  STRIDE_DETAIL_UNPARENTHESISED(TYPE) NAME

// `(std::array<double, 3>)` -> `std::array<double, 3>`; `double` stays `double`.
#define STRIDE_DETAIL_UNPARENTHESISED(X) STRIDE_DETAIL_ESCAPE(STRIDE_DETAIL_ISH X)
#define STRIDE_DETAIL_ISH(...) STRIDE_DETAIL_ISH __VA_ARGS__
#define STRIDE_DETAIL_ESCAPE(...) STRIDE_DETAIL_ESCAPE_(__VA_ARGS__)
#define STRIDE_DETAIL_ESCAPE_(...) STRIDE_DETAIL_VAN##__VA_ARGS__
#define STRIDE_DETAIL_VANSTRIDE_DETAIL_ISH
