#include "polygonize/field_source.hpp"

#include "accel/support_shapes.hpp"

namespace convray::polygonize {

std::vector<Box3> triangle_support_boxes(std::span<const field::Triangle> triangles,
                                         double radius) {
  std::vector<Box3> boxes;
  boxes.reserve(triangles.size());
  for (const field::Triangle& triangle : triangles) {
    boxes.push_back(accel::triangle_support_box(triangle, radius));
  }
  return boxes;
}

}  // namespace convray::polygonize
