#include "mesh/exact_predicates.hpp"

#include <cmath>
#include <vector>

namespace convray::mesh {
namespace {

// An exact real number as a sum of doubles in increasing magnitude, no two overlapping in
// their bits and none zero; its sign is therefore the sign of its last (largest) part.
using Expansion = std::vector<double>;

// a + b = x + y exactly, x being the rounded sum (Knuth's two-sum; no ordering needed).
void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  y = (a - a_virtual) + (b - b_virtual);
}

// e += b, keeping e an expansion (Shewchuk's Grow-Expansion with zero elimination).
void grow(Expansion& e, double b) {
  double carry = b;
  size_t kept = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    double sum, error;
    two_sum(carry, e[i], sum, error);
    carry = sum;
    if (error != 0.0) e[kept++] = error;
  }
  e.resize(kept);
  if (carry != 0.0) e.push_back(carry);
}

Expansion sum(Expansion e, const Expansion& f) {
  for (double part : f) grow(e, part);
  return e;
}

Expansion negated(Expansion e) {
  for (double& part : e) part = -part;
  return e;
}

// Every product of parts is split exactly into its rounded value and the rounding error (the
// fused multiply-add computes the error without rounding), then summed exactly.
Expansion product(const Expansion& e, const Expansion& f) {
  Expansion result;
  for (double x : e) {
    for (double y : f) {
      const double rounded = x * y;
      grow(result, std::fma(x, y, -rounded));
      grow(result, rounded);
    }
  }
  return result;
}

Expansion difference(double a, double b) {
  Expansion e;
  grow(e, a);
  grow(e, -b);
  return e;
}

int sign(const Expansion& e) { return e.empty() ? 0 : (e.back() > 0.0 ? 1 : -1); }

int sign(double x) { return (x > 0.0) - (x < 0.0); }

// det[p, q] of two 2-vectors given as expansions.
Expansion det2(const Expansion& px, const Expansion& py, const Expansion& qx, const Expansion& qy) {
  return sum(product(px, qy), negated(product(py, qx)));
}

// Rounding-error bounds of the plain double evaluations below, relative to the sum of the
// absolute values of their products: twice Shewchuk's first-stage bounds (3 eps and 7 eps,
// eps = 2^-53), so that a sign the filter accepts is certainly right.
constexpr double kEpsilon = 0x1p-53;
constexpr double kBound2d = 8.0 * kEpsilon;
constexpr double kBound3d = 16.0 * kEpsilon;

}  // namespace

int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) {
  return sign(
      det2(difference(b.x, a.x), difference(b.y, a.y), difference(c.x, a.x), difference(c.y, a.y)));
}

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  Expansion u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = difference(b[k], a[k]);
    v[k] = difference(c[k], a[k]);
    w[k] = difference(d[k], a[k]);
  }
  // Expansion along the first row: u.x (v.y w.z - v.z w.y) - u.y (...) + u.z (...).
  const Expansion minor_x = det2(v[1], v[2], w[1], w[2]);
  const Expansion minor_y = det2(v[0], v[2], w[0], w[2]);
  const Expansion minor_z = det2(v[0], v[1], w[0], w[1]);
  return sign(
      sum(sum(product(u[0], minor_x), negated(product(u[1], minor_y))), product(u[2], minor_z)));
}

int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double left = (b.x - a.x) * (c.y - a.y);
  const double right = (b.y - a.y) * (c.x - a.x);
  const double det = left - right;
  if (std::abs(det) > kBound2d * (std::abs(left) + std::abs(right))) return sign(det);
  return orient2d_exact(a, b, c);
}

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double x1 = v.y * w.z, x2 = v.z * w.y;
  const double y1 = v.x * w.z, y2 = v.z * w.x;
  const double z1 = v.x * w.y, z2 = v.y * w.x;
  const double det = u.x * (x1 - x2) - u.y * (y1 - y2) + u.z * (z1 - z2);
  const double permanent = std::abs(u.x) * (std::abs(x1) + std::abs(x2)) +
                           std::abs(u.y) * (std::abs(y1) + std::abs(y2)) +
                           std::abs(u.z) * (std::abs(z1) + std::abs(z2));
  if (std::abs(det) > kBound3d * permanent) return sign(det);
  return orient3d_exact(a, b, c, d);
}

}  // namespace convray::mesh
