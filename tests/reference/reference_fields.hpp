#pragma once
// Independent numerical references for the convolution fields of every skeleton primitive.
// They integrate the kernel f(r^2) = (1 - r^2/R^2)^2 (r <= R) by quadrature straight from the
// definition F(P) = integral over the primitive of f(|P - Q|^2) dQ, and the gradient as the
// quadrature of the differentiated integrand -(4/R^2) (1 - |P-Q|^2/R^2) (P - Q) (the kernel has
// zero slope at r = R, so there are no boundary terms). No closed form from src/field is used;
// the arguments are plain vectors so that the references do not depend on src/field at all.
#include "util/math.hpp"

namespace convray::reference {

struct ReferenceSample {
  double value = 0.0;
  Vec3 gradient{0.0};
  double error_estimate = 0.0;  // quadrature error estimate, in the units of the value
  bool converged = true;
};

// Relative accuracy requested from the adaptive quadratures: the absolute tolerance is this
// times the natural scale of the primitive (R^2 for areas, R for curves).
inline constexpr double kReferenceTolerance = 1e-14;

// The kernel itself: (1 - d^2/R^2)^2 for d <= R, else 0, and its gradient.
ReferenceSample reference_point(const Vec3& p, const Vec3& center, double radius);

// Adaptive Gauss-Kronrod along the segment a-b, split where the line enters and leaves the
// support sphere. A zero-length segment gives 0.
ReferenceSample reference_segment(const Vec3& p, const Vec3& a, const Vec3& b, double radius);

// Arc points center + arc_radius * (cos t * start + sin t * (axis x start)), t in [0, angle],
// integrated over arc length (arc_radius dt), split where the circle meets the support sphere.
ReferenceSample reference_arc(const Vec3& p, const Vec3& center, const Vec3& axis,
                              const Vec3& start, double arc_radius, double angle, double radius);

// Polar quadrature around O, the projection of p on the triangle's plane: for each direction
// theta the ray from O crosses the triangle in [rho_in, rho_out], clipped to [0, r0] with
// r0^2 = R^2 - h^2; the radial integral is Gauss-Legendre (exact: the integrand times rho is a
// polynomial), the angular one adaptive Gauss-Kronrod split at the vertex directions and at the
// directions where the circle of radius r0 crosses an edge. Zero-area triangles give 0.
ReferenceSample reference_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                   double radius);

}  // namespace convray::reference
