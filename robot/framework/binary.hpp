#pragma once
// Typed side of reflection: the TypeDesc of a C++ type, and its compact binary encoding.
// Supported: bool, int8/uint8/int32/uint32/int64, float, double, std::string, named enums,
// std::array, std::vector, fixed-size Eigen matrices, and reflected structs of these.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "robot/framework/type_desc.hpp"

namespace stride {

namespace detail {
template <class T>
struct IsStdArray : std::false_type {};
template <class T, std::size_t N>
struct IsStdArray<std::array<T, N>> : std::true_type {};
template <class T>
struct IsStdVector : std::false_type {};
template <class T, class A>
struct IsStdVector<std::vector<T, A>> : std::true_type {};
template <class T>
concept FixedEigen = std::is_base_of_v<Eigen::MatrixBase<T>, T> &&(T::RowsAtCompileTime > 0) &&
                     (T::ColsAtCompileTime > 0);
template <class T>
constexpr bool kAlwaysFalse = false;

template <class T>
TypeDescPtr leaf(Kind k, std::string name) {
  auto d = std::make_shared<TypeDesc>();
  d->kind = k;
  d->name = std::move(name);
  return d;
}
inline TypeDescPtr array_of(TypeDescPtr element, std::size_t n, bool components = false) {
  auto d = std::make_shared<TypeDesc>();
  d->kind = Kind::Array;
  d->name = "array";
  d->length = n;
  d->element = std::move(element);
  d->vector_components = components;
  return d;
}
}  // namespace detail

template <class T>
TypeDescPtr describe();

namespace detail {
template <class T>
TypeDescPtr make_desc() {
  if constexpr (std::is_same_v<T, bool>)
    return leaf<T>(Kind::Bool, "bool");
  else if constexpr (std::is_same_v<T, std::int8_t>)
    return leaf<T>(Kind::Int8, "int8");
  else if constexpr (std::is_same_v<T, std::uint8_t>)
    return leaf<T>(Kind::UInt8, "uint8");
  else if constexpr (std::is_same_v<T, std::int32_t>)
    return leaf<T>(Kind::Int32, "int32");
  else if constexpr (std::is_same_v<T, std::uint32_t>)
    return leaf<T>(Kind::UInt32, "uint32");
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return leaf<T>(Kind::Int64, "int64");
  else if constexpr (std::is_same_v<T, float>)
    return leaf<T>(Kind::Float, "float");
  else if constexpr (std::is_same_v<T, double>)
    return leaf<T>(Kind::Double, "double");
  else if constexpr (std::is_same_v<T, std::string>)
    return leaf<T>(Kind::String, "string");
  else if constexpr (NamedEnum<T>) {
    auto d = std::make_shared<TypeDesc>();
    d->kind = Kind::Enum;
    d->name = std::string(EnumNames<T>::type_name);
    for (auto n : EnumNames<T>::names) d->enumerators.emplace_back(n);
    return d;
  } else if constexpr (IsStdArray<T>::value) {
    return array_of(describe<typename T::value_type>(), std::tuple_size_v<T>);
  } else if constexpr (IsStdVector<T>::value) {
    auto d = std::make_shared<TypeDesc>();
    d->kind = Kind::List;
    d->name = "list";
    d->element = describe<typename T::value_type>();
    return d;
  } else if constexpr (FixedEigen<T>) {
    auto scalar = describe<typename T::Scalar>();
    if constexpr (T::RowsAtCompileTime == 1 || T::ColsAtCompileTime == 1)
      return array_of(scalar, T::SizeAtCompileTime, T::SizeAtCompileTime <= 4);
    else  // row-major: a list of rows
      return array_of(array_of(scalar, T::ColsAtCompileTime), T::RowsAtCompileTime);
  } else if constexpr (Reflected<T>) {
    auto d = std::make_shared<TypeDesc>();
    d->kind = Kind::Struct;
    d->name = std::string(Reflect<T>::type_name());
    for_each_field<T>([&](const auto& f) {
      using M = std::remove_cvref_t<decltype(std::declval<T&>().*(f.member))>;
      TypeDescPtr type = describe<M>();
      if (!f.element_names.empty()) type = with_element_names(type, f.element_names);
      d->fields.push_back(FieldDesc{std::string(f.name), std::string(f.unit), f.range, type});
    });
    return d;
  } else {
    static_assert(kAlwaysFalse<T>, "type is not supported by stride reflection");
  }
}
}  // namespace detail

// One immutable description per type, built on first use.
template <class T>
TypeDescPtr describe() {
  static const TypeDescPtr d = detail::make_desc<T>();
  return d;
}

template <class T>
void encode(ByteWriter& w, const T& v) {
  if constexpr (std::is_arithmetic_v<T>)
    w.put(v);
  else if constexpr (std::is_same_v<T, std::string>)
    w.put_string(v);
  else if constexpr (NamedEnum<T>)
    w.put(static_cast<std::int32_t>(v));
  else if constexpr (detail::IsStdArray<T>::value) {
    if constexpr (std::is_arithmetic_v<typename T::value_type>)
      w.buffer().append(reinterpret_cast<const char*>(v.data()), sizeof(T));
    else
      for (const auto& e : v) encode(w, e);
  } else if constexpr (detail::IsStdVector<T>::value) {
    w.put(static_cast<std::uint32_t>(v.size()));
    for (const auto& e : v) encode(w, e);
  } else if constexpr (detail::FixedEigen<T>) {
    for (int r = 0; r < v.rows(); ++r)
      for (int c = 0; c < v.cols(); ++c) w.put(v(r, c));
  } else {
    for_each_field<T>([&](const auto& f) { encode(w, v.*(f.member)); });
  }
}

template <class T>
void decode(ByteReader& r, T& v) {
  if constexpr (std::is_same_v<T, bool>)
    v = r.get<std::uint8_t>() != 0;
  else if constexpr (std::is_arithmetic_v<T>)
    v = r.get<T>();
  else if constexpr (std::is_same_v<T, std::string>)
    v = r.get_string();
  else if constexpr (NamedEnum<T>) {
    const auto i = r.get<std::int32_t>();
    if (i < 0 || i >= static_cast<std::int32_t>(EnumNames<T>::names.size()))
      throw Error(std::string(EnumNames<T>::type_name) + ": no enumerator " + std::to_string(i));
    v = static_cast<T>(i);
  } else if constexpr (detail::IsStdArray<T>::value) {
    for (auto& e : v) decode(r, e);
  } else if constexpr (detail::IsStdVector<T>::value) {
    const auto n = r.get<std::uint32_t>();
    if (n > r.remaining())
      throw Error("binary data: list length " + std::to_string(n) + " too large");
    v.resize(n);
    for (auto& e : v) decode(r, e);
  } else if constexpr (detail::FixedEigen<T>) {
    for (int row = 0; row < v.rows(); ++row)
      for (int c = 0; c < v.cols(); ++c) v(row, c) = r.get<typename T::Scalar>();
  } else {
    for_each_field<T>([&](const auto& f) { decode(r, v.*(f.member)); });
  }
}

template <class T>
std::string to_binary(const T& v) {
  std::string out;
  ByteWriter w(out);
  encode(w, v);
  return out;
}

// Decodes the whole of `bytes` into a copy first, so a malformed input leaves `v` unchanged.
template <class T>
void from_binary(T& v, std::string_view bytes) {
  ByteReader r(bytes);
  T tmp = v;
  decode(r, tmp);
  if (r.remaining() != 0)
    throw Error("binary data: " + std::to_string(r.remaining()) + " bytes left after decoding");
  v = std::move(tmp);
}

}  // namespace stride
