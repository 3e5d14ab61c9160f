#pragma once
// POV-Ray 3.7 blob components, with POV-Ray's exact semantics, so its blobs can be reproduced.
// Both use the distance kernel strength * (1 - d^2/r^2)^2 for d < r, else 0 (no integral):
//  - sphere: d is the distance to the centre;
//  - cylinder: a capsule, d is the distance to the axis segment (to the axis along the body,
//    to the nearer end point beyond it), which is why POV-Ray's cylinder joints bulge.
#include "field/sample.hpp"

namespace convray::field {

FieldSample blob_sphere_field(const Vec3& p, const Vec3& center, double radius, double strength);
FieldSample blob_cylinder_field(const Vec3& p, const Vec3& base, const Vec3& apex, double radius,
                                double strength);

}  // namespace convray::field
