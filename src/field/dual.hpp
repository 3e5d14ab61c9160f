#pragma once
// Forward-mode dual numbers carrying a value and its gradient with respect to the evaluation
// point P. Running a closed form on them gives the gradient exact to rounding, with no finite
// differences. Only the operations the closed forms use are defined.
#include <cmath>

#include "util/math.hpp"

namespace convray::field {

struct Dual {
  double v = 0.0;   // value
  Vec3 d{0.0};      // gradient with respect to P

  Dual() = default;
  Dual(double value) : v(value) {}  // a constant: zero gradient
  Dual(double value, const Vec3& grad) : v(value), d(grad) {}
};

inline Dual operator+(const Dual& a, const Dual& b) { return {a.v + b.v, a.d + b.d}; }
inline Dual operator-(const Dual& a, const Dual& b) { return {a.v - b.v, a.d - b.d}; }
inline Dual operator-(const Dual& a) { return {-a.v, -a.d}; }
inline Dual operator*(const Dual& a, const Dual& b) { return {a.v * b.v, a.d * b.v + b.d * a.v}; }
inline Dual operator*(double s, const Dual& a) { return {s * a.v, s * a.d}; }
inline Dual operator*(const Dual& a, double s) { return {s * a.v, s * a.d}; }
inline Dual operator/(const Dual& a, double s) { return {a.v / s, a.d / s}; }
inline Dual& operator+=(Dual& a, const Dual& b) { return a = a + b; }

// atan2(y, x): d = (x dy - y dx) / (x^2 + y^2). Callers never pass (0, 0) with a gradient.
inline Dual atan2(const Dual& y, const Dual& x) {
  const double r2 = x.v * x.v + y.v * y.v;
  const Vec3 grad = r2 > 0.0 ? (x.v * y.d - y.v * x.d) / r2 : Vec3(0.0);
  return {std::atan2(y.v, x.v), grad};
}

// A quantity that depends on P, built from its value and gradient: a Dual when the gradient
// is wanted, the plain value otherwise.
template <class S>
S variable(double value, const Vec3& gradient);
template <>
inline double variable<double>(double value, const Vec3&) { return value; }
template <>
inline Dual variable<Dual>(double value, const Vec3& gradient) { return {value, gradient}; }

inline double value_of(double x) { return x; }
inline double value_of(const Dual& x) { return x.v; }

}  // namespace convray::field
