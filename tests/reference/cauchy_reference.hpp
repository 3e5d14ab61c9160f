#pragma once
// Independent numerical references for the Cauchy kernel h(r) = 1 / (1 + s^2 r^2)^2 of
// McCormack and Sherstyuk convolved with segments and triangles: adaptive Gauss-Kronrod
// quadrature straight from the definition F(P) = integral over the primitive of h(|P - Q|),
// and the gradient as the quadrature of the differentiated integrand
// -4 s^2 (P - Q) / (1 + s^2 |P - Q|^2)^3 (the kernel is smooth and bounded, so nothing is
// singular). No closed form from src/field is used.
#include "reference/reference_fields.hpp"

namespace convray::reference {

// The kernel and its gradient at p.
ReferenceSample reference_cauchy_point(const Vec3& p, const Vec3& center, double s);

// Adaptive quadrature along the segment, split at the foot of the perpendicular from p.
ReferenceSample reference_cauchy_segment(const Vec3& p, const Vec3& a, const Vec3& b, double s);

// Nested adaptive quadrature in the triangle's own coordinates: Q = a + u (b - a) + v (c - a),
// u in [0, 1] outside, v in [0, 1 - u] inside (split where the line of constant u passes
// nearest to p, where the peak of the integrand is). Zero-area triangles give 0.
ReferenceSample reference_cauchy_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c, double s);

}  // namespace convray::reference
