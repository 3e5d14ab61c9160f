#pragma once
// Field of a circular-arc skeleton: the kernel integrated along the arc (closed form).
#include "field/sample.hpp"

namespace convray::field {

// Points center + radius * (cos t * start + sin t * (axis x start)) for t in [0, angle].
// axis and start are unit vectors, start perpendicular to axis; 0 < angle <= 2 pi.
struct Arc {
  Vec3 center;
  Vec3 axis;
  Vec3 start;
  double radius = 1.0;
  double angle = 2.0 * kPi;

  Vec3 point_at(double t) const;
};

// Builds an arc through three points: from `first`, passing `through`, ending at `last`.
// Returns false when the points are collinear or coincide.
bool arc_through(const Vec3& first, const Vec3& through, const Vec3& last, Arc& out);

// Raw field (strength 1): integral over arc length of the kernel with support radius R.
double arc_value(const Vec3& p, const Arc& arc, double radius);
FieldSample arc_field(const Vec3& p, const Arc& arc, double radius);

}  // namespace convray::field
