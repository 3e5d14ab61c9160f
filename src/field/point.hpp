#pragma once
// Field of a point skeleton: the quartic kernel itself, (1 - d^2/R^2)^2 for d <= R, else 0.
#include "field/sample.hpp"

namespace convray::field {

double point_value(const Vec3& p, const Vec3& center, double radius);
FieldSample point_field(const Vec3& p, const Vec3& center, double radius);

}  // namespace convray::field
