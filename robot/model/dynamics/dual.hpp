#pragma once
// Forward-mode dual number (value + one derivative): exact partial derivatives of the closed-form
// kinematics, used for the Christoffel symbols (Eq. C.14) without symbolic algebra.
#include <cmath>

namespace stride::model {

struct Dual {
  double v = 0, d = 0;
  Dual() = default;
  Dual(double value, double derivative = 0) : v(value), d(derivative) {}
};

inline Dual operator+(Dual a, Dual b) {
  return {a.v + b.v, a.d + b.d};
}
inline Dual operator-(Dual a, Dual b) {
  return {a.v - b.v, a.d - b.d};
}
inline Dual operator-(Dual a) {
  return {-a.v, -a.d};
}
inline Dual operator*(Dual a, Dual b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d};
}
inline Dual& operator+=(Dual& a, Dual b) {
  return a = a + b;
}
inline Dual sin(Dual a) {
  return {std::sin(a.v), std::cos(a.v) * a.d};
}
inline Dual cos(Dual a) {
  return {std::cos(a.v), -std::sin(a.v) * a.d};
}

inline double value(double x) {
  return x;
}
inline double value(Dual x) {
  return x.v;
}

}  // namespace stride::model
