#include "mesh/soup.hpp"

#include <algorithm>

namespace convray::mesh {

Box3 TriangleSoup::bounds() const {
  Box3 box;
  for (const Triangle& tri : triangles) {
    for (uint32_t index : tri) box.extend(vertices[index]);
  }
  return box;
}

void fit_into_box(TriangleSoup& soup, double size) { fit_into_box(soup.vertices, soup.bounds(), size); }

void fit_into_box(std::vector<Vec3>& vertices, const Box3& box, double size) {
  if (box.empty()) return;
  const Vec3 extent = box.extent();
  const double largest = std::max({extent.x, extent.y, extent.z});
  const Vec3 center = 0.5 * (box.lo + box.hi);
  const double scale = largest > 0.0 ? size / largest : 1.0;
  for (Vec3& v : vertices) v = (v - center) * scale;
}

}  // namespace convray::mesh
