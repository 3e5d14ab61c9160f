#include "implicit/placed_field.hpp"

#include "core/box.hpp"

namespace convray::implicit {

field::FieldSample placed_field(const Surface& surface, const scene::Transform& placed,
                                const Vec3& p) {
  field::FieldSample s = surface.field(placed.inverse_point(p));
  s.gradient = placed.normal(s.gradient);
  return s;
}

std::vector<Box3> placed_support_boxes(const Surface& surface, const scene::Transform& placed) {
  std::vector<Box3> boxes = surface.support_boxes();
  for (Box3& box : boxes) box = transform_box(placed.forward(), box);
  return boxes;
}

}  // namespace convray::implicit
