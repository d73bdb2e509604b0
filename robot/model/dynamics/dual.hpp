#pragma once
// Forward-mode dual numbers (value + one derivative): exact partial derivatives of the closed-form
// kinematics, used for the Christoffel symbols (Eq. C.14) without symbolic algebra. Nesting
// (DualOf<Dual>) gives exact second derivatives.
#include <cmath>

namespace stride::model {

template <typename T>
struct DualOf {
  T v{}, d{};
  DualOf() = default;
  DualOf(double value) : v(value), d(0.0) {}  // NOLINT: constants promote implicitly
  DualOf(T value, T derivative) : v(value), d(derivative) {}
};

using Dual = DualOf<double>;
using Dual2 = DualOf<Dual>;

template <typename T>
DualOf<T> operator+(const DualOf<T>& a, const DualOf<T>& b) {
  return {a.v + b.v, a.d + b.d};
}
template <typename T>
DualOf<T> operator-(const DualOf<T>& a, const DualOf<T>& b) {
  return {a.v - b.v, a.d - b.d};
}
template <typename T>
DualOf<T> operator-(const DualOf<T>& a) {
  return {-a.v, -a.d};
}
template <typename T>
DualOf<T> operator*(const DualOf<T>& a, const DualOf<T>& b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d};
}
template <typename T>
DualOf<T> operator*(double a, const DualOf<T>& b) {
  return {a * b.v, a * b.d};
}
template <typename T>
DualOf<T>& operator+=(DualOf<T>& a, const DualOf<T>& b) {
  return a = a + b;
}
template <typename T>
DualOf<T> sin(const DualOf<T>& a) {
  using std::cos, std::sin;
  return {sin(a.v), cos(a.v) * a.d};
}
template <typename T>
DualOf<T> cos(const DualOf<T>& a) {
  using std::cos, std::sin;
  return {cos(a.v), -sin(a.v) * a.d};
}

}  // namespace stride::model
