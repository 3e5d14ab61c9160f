#pragma once
// Field of a triangle skeleton: the paper's convolution of the quartic kernel with a triangle,
// in closed form for every configuration of the clipping sphere and the triangle.
#include "field/sample.hpp"

namespace convray::field {

struct Triangle {
  Vec3 a, b, c;
};

// Raw field (strength 1): integral over the triangle's area of (1 - |p-q|^2/R^2)^2, clipped at R.
// Zero-area triangles give 0.
double triangle_value(const Vec3& p, const Triangle& triangle, double radius);
FieldSample triangle_field(const Vec3& p, const Triangle& triangle, double radius);

}  // namespace convray::field
