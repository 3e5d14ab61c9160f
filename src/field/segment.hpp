#pragma once
// Field of a line-segment skeleton: the kernel integrated along the segment (closed form).
#include "field/sample.hpp"

namespace convray::field {

struct Segment {
  Vec3 a, b;
};

// Raw field (strength 1): integral over the segment of (1 - |p-q|^2/R^2)^2, clipped at R.
double segment_value(const Vec3& p, const Segment& segment, double radius);
FieldSample segment_field(const Vec3& p, const Segment& segment, double radius);

}  // namespace convray::field
