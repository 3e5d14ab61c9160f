#pragma once
// A triangle's raw field along a line while the whole triangle lies inside the kernel's ball:
// then no clipping happens, and the integral of (1 - |p(s) - q|^2 / R^2)^2 over the triangle,
// with p(s) = origin + s direction, is a polynomial of degree 4 in s. Its coefficients are
// integrals of polynomials of degree at most 4 over the triangle, computed exactly (up to
// rounding) by Dunavant's 6-point rule, which integrates every polynomial of degree 4 exactly
// (D. A. Dunavant, "High degree efficient symmetrical Gaussian quadrature rules for the
// triangle", IJNME 21, 1985). The exact twin is triangle_value (triangle.hpp).
#include <cstdint>
#include <span>

#include "field/triangle.hpp"
#include "field/triangle_frame.hpp"
#include "util/math.hpp"

namespace convray::field {

// c[0] + c[1] s + c[2] s^2 + c[3] s^3 + c[4] s^4.
struct LineQuartic {
  double c[5] = {0.0, 0.0, 0.0, 0.0, 0.0};

  double value(double s) const { return c[0] + s * (c[1] + s * (c[2] + s * (c[3] + s * c[4]))); }
  double slope(double s) const {
    return c[1] + s * (2.0 * c[2] + s * (3.0 * c[3] + s * 4.0 * c[4]));
  }
  void add(const LineQuartic& o, double weight) {
    for (int k = 0; k < 5; ++k) c[k] += weight * o.c[k];
  }
};

// The quartic of `triangle` along origin + s direction (direction of unit length); equal to
// triangle_value(origin + s direction, triangle, radius) wherever all three corners are within
// `radius` of that point. `area`: the triangle's, triangle_frame(triangle).area (computed once
// per mesh; its square root was a fifth of this function's time).
LineQuartic triangle_line_quartic(const Triangle& triangle, double area, const Vec3& origin,
                                  const Vec3& direction, double radius);

// The same for the triangles `ids` of `triangles` (their frames' areas) at once, in SIMD
// lanes: out[k] is triangle_line_quartic of triangles[ids[k]], to the bit. The window march
// makes a sample's new quartics together (one at a time, they were 4 % of the dragon's
// render at R = 5).
void triangle_line_quartics(std::span<const Triangle> triangles,
                            std::span<const TriangleFrame> frames, std::span<const uint32_t> ids,
                            const Vec3& origin, const Vec3& direction, double radius,
                            std::span<LineQuartic> out);

}  // namespace convray::field
