#include "field/triangle.hpp"

#include <array>
#include <cmath>

#include "field/dual.hpp"

namespace convray::field {

// The integral over triangle ∩ disk, without the paper's six-case analysis (DESIGN.md §4).
//
// Let O be the projection of P on the triangle's plane, h the signed height of P above it and
// r0^2 = R^2 - h^2 the squared radius of the disk where the kernel is non-zero. In the plane the
// integrand is g(ρ) = ((r0^2 - ρ^2)/R^2)^2, ρ = |Q - O|. The triangle is the signed sum of the
// three fan triangles (O, V_i, V_i+1), so the field is a sum over edges. For one edge, with
// s the coordinate along it measured from the foot of O and d the signed distance of O to its
// line (positive when O lies on the triangle's side), the fan triangle ∩ disk splits into
//  - the part of the edge inside the disk (|s| <= w, w^2 = r0^2 - d^2): in polar coordinates
//    the radial integral of g ρ is (r0^6 - (r0^2 - ρ^2)^3)/(6R^4), and substituting
//    ψ = atan(s/d) leaves a polynomial in s:
//      d [ (3r0^4 - 3r0^2 d^2 + d^4) s - (r0^2 - 2d^2/3) s^3 + s^5/5 ] / (6R^4);
//  - the parts outside the disk: pie slices of the full disk, r0^6/(6R^4) times the angle
//    they subtend at O (the paper's Eq. 7).
// The sign of d makes every term signed, so no case analysis is needed. The clip points
// s = +-w move with P, but the two parts meet continuously there, so their derivatives cancel
// and w is treated as a constant when differentiating.

namespace {

// Antiderivative difference of the inside-the-disk part over [s1, s2], times 6R^4.
template <class S>
S fan_inside_part(const S& d, const S& s1, const S& s2, const S& r0sq) {
  const S d2 = d * d;
  const S linear = 3.0 * r0sq * r0sq - 3.0 * r0sq * d2 + d2 * d2;
  const S cubic = r0sq - (2.0 / 3.0) * d2;
  const S s1_2 = s1 * s1;
  const S s2_2 = s2 * s2;
  const S delta1 = s2 - s1;
  const S delta3 = s2 * s2_2 - s1 * s1_2;
  const S delta5 = s2 * s2_2 * s2_2 - s1 * s1_2 * s1_2;
  return d * (linear * delta1 - cubic * delta3 + delta5 / 5.0);
}

// Signed angle subtended at O by the stretch [s1, s2] (s1 < s2) of the edge's line.
template <class S>
S subtended_angle(const S& d, const S& s1, const S& s2) {
  using std::atan2;  // plain doubles; Dual finds its own overload
  return atan2(d * (s2 - s1), d * d + s1 * s2);
}

// One fan triangle: its part inside the disk plus its pie slices, times 6R^4.
template <class S>
S fan_integral(const S& d, const S& s_begin, const S& s_end, const S& r0sq, bool& touches_disk) {
  const double d_value = value_of(d);
  const double w2 = value_of(r0sq) - d_value * d_value;
  const double w = w2 > 0.0 ? std::sqrt(w2) : 0.0;
  const double begin = value_of(s_begin);
  const double end = value_of(s_end);
  S total(0.0);
  S pie_angle(0.0);
  // A corner exactly on the circle is a moving bound, not a fixed clip point: both sides'
  // derivatives agree there, so it must carry its gradient (hence >= and <=).
  const S lo = begin >= -w ? s_begin : S(-w);
  const S hi = end <= w ? s_end : S(w);
  if (value_of(lo) < value_of(hi)) {
    touches_disk = true;
    total += fan_inside_part(d, lo, hi, r0sq);
  }
  if (begin < -w) pie_angle += subtended_angle(d, s_begin, end <= -w ? s_end : S(-w));
  if (end > w) pie_angle += subtended_angle(d, begin >= w ? s_begin : S(w), s_end);
  return total + r0sq * r0sq * r0sq * pie_angle;
}

template <class S>
S triangle_integral(const Vec3& p, const Triangle& triangle, double radius) {
  const std::array<Vec3, 3> v{triangle.a, triangle.b, triangle.c};
  const Vec3 cross = glm::cross(v[1] - v[0], v[2] - v[0]);
  const double cross_length = glm::length(cross);
  if (!(cross_length > 0.0)) return S(0.0);  // zero area: zero integral
  const Vec3 n = cross / cross_length;
  const double r2 = radius * radius;
  const double h = glm::dot(p - v[0], n);
  if (!(h * h < r2)) return S(0.0);
  const S r0sq = variable<S>(r2 - h * h, (-2.0 * h) * n);

  S sum(0.0);
  bool touches_disk = false;
  bool o_inside = true;
  for (int i = 0; i < 3; ++i) {
    const Vec3 edge = v[(i + 1) % 3] - v[i];
    const double length = glm::length(edge);
    const Vec3 u = edge / length;
    const Vec3 m = glm::cross(u, n);  // in-plane normal pointing into the triangle
    const Vec3 rel = v[i] - p;
    const S d = variable<S>(glm::dot(rel, m), -m);
    const S s_begin = variable<S>(glm::dot(rel, u), -u);
    const S s_end = s_begin + S(length);
    o_inside = o_inside && value_of(d) >= 0.0;
    sum += fan_integral(d, s_begin, s_end, r0sq, touches_disk);
  }
  // No edge reaches the disk: it lies wholly inside or wholly outside the triangle. Return
  // the exact answers rather than the pie angles' rounding residue.
  if (!touches_disk) sum = o_inside ? 2.0 * kPi * r0sq * r0sq * r0sq : S(0.0);
  return sum / (6.0 * r2 * r2);
}

}  // namespace

double triangle_value(const Vec3& p, const Triangle& triangle, double radius) {
  return triangle_integral<double>(p, triangle, radius);
}

FieldSample triangle_field(const Vec3& p, const Triangle& triangle, double radius) {
  const Dual f = triangle_integral<Dual>(p, triangle, radius);
  return {f.v, f.d};
}

}  // namespace convray::field
