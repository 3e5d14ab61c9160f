#pragma once
// Two of a triangle's pie angles (TriangleBatch, triangle.cpp: the angle each edge's parts
// outside the kernel's disk subtend) summed with one atan2: the angle of the product of the
// pies (x + i y), which is their sum up to a whole turn. Each angle lies in [-pi, pi] with the
// sign bit of its y (atan2(-0, x) is -0 or -pi), so the sum lies in [0, 2 pi] where neither y
// has its sign bit set, in [-2 pi, -0] where both have, and in [-pi, pi] otherwise: in the
// first case a product's angle with its sign bit set is a turn short, in the second one
// without it a turn over. Rounding keeps to those signs: where the sum is near 0 or near a
// whole turn in the first two cases, both x have one sign and the product's y is a sum of two
// products of one sign. A pie (±0, ±0), whose angle is that of (±0, ±1), is made that, so
// that its signs still count; `scale` (> 0, no angle changes) keeps the product in range.
// Three pies in one product leave the turn unknown in general (their sum spans 3 pi); a
// triangle's three, whose sum is known to lie within a turn, are three_pie_angles' below.
//
// `atan2` is the caller's (a SIMD variant in the batch's vectorized loop); only selects on
// comparisons of doubles, which GCC's vectorizer takes where it leaves a bool's loop scalar.
#include <algorithm>
#include <cmath>

#include "util/math.hpp"

namespace convray::field {

// A pie made ready for a product: scaled, and a zero pie (±0, ±0) made (±1, ±0), the pie
// whose angle atan2 gives it.
[[gnu::always_inline]] inline void scale_pie(double& y, double& x, double scale) {
  x = x == 0.0 ? (y == 0.0 ? std::copysign(1.0, x) : x) : x * scale;
  y *= scale;
}

template <class Atan2>
[[gnu::always_inline]] inline double two_pie_angles(double y0, double x0, double y1, double x1,
                                                    double scale, Atan2 atan2) {
  scale_pie(y0, x0, scale);
  scale_pie(y1, x1, scale);
  const double angle = atan2(x0 * y1 + y0 * x1, x0 * x1 - y0 * y1);
  const double signs = std::copysign(1.0, y0) + std::copysign(1.0, y1);  // 2, 0 or -2
  const double side = std::copysign(1.0, angle);
  const double short_turn = side < 0.0 ? 2.0 * kPi : 0.0;
  const double over_turn = side > 0.0 ? -2.0 * kPi : 0.0;
  return angle + (signs > 0.0 ? short_turn : signs < 0.0 ? over_turn : 0.0);
}

// All three of a triangle's pie angles summed with one atan2, where their sum is known to lie
// in [0, 2 pi]: the arc of the kernel's circle inside the triangle (the edges' parts outside
// the disk subtend, seen from its centre, what the triangle's boundary does less what its parts
// inside the disk do, and the region they bound with the arcs holds the centre exactly when the
// triangle does). The product of the three pies has the sum's angle up to whole turns: a turn
// is added where that angle is negative. Only where it lies within kTurnDoubt of 0 may the sum
// be either 0 or a whole turn (rounding decides), and where the product leaves the doubles'
// comfortable range its angle is unsure: `doubtful` is 1 then, else 0, for the caller to sum
// that lane's angles the two-call way. Zero pies as in two_pie_angles.
inline constexpr double kTurnDoubt = 1e-9;

template <class Atan2>
[[gnu::always_inline]] inline double three_pie_angles(double y0, double x0, double y1, double x1,
                                                      double y2, double x2, double scale,
                                                      Atan2 atan2, double& doubtful) {
  scale_pie(y0, x0, scale);
  scale_pie(y1, x1, scale);
  scale_pie(y2, x2, scale);
  const double x01 = x0 * x1 - y0 * y1, y01 = x0 * y1 + y0 * x1;
  const double x = x01 * x2 - y01 * y2, y = x01 * y2 + y01 * x2;
  const double angle = atan2(y, x);
  const double size = std::max(std::abs(x), std::abs(y));
  doubtful = std::abs(angle) < kTurnDoubt || !(size > 1e-250) || !(size < 1e250) ? 1.0 : 0.0;
  return angle < 0.0 ? angle + 2.0 * kPi : angle;
}

}  // namespace convray::field
