#pragma once
// The polygon soup every other module consumes: positions plus index triples, nothing else.
// No connectivity is implied: two triangles may share a position without sharing an index
// (STL stores every corner separately); src/mesh/stats.hpp welds positions when it matters.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "util/math.hpp"

namespace convray::mesh {

using Triangle = std::array<uint32_t, 3>;

struct TriangleSoup {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;  // indices into vertices, counter-clockwise seen from outside

  // Box around the corners of the triangles; vertices no triangle uses do not count, since
  // the surface is what gets rendered. Empty (Box3::empty()) when there are no triangles.
  Box3 bounds() const;

  // Number of triangles.
  size_t size() const { return triangles.size(); }

  // The three corner positions of triangle t.
  std::array<Vec3, 3> corners(size_t t) const {
    const Triangle& tri = triangles[t];
    return {vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]};
  }
};

// The paper's protocol (Table 1): scale uniformly so that the largest extent of the bounds is
// `size`, and centre the bounds at the origin (400 fills (-200,-200,-200)-(200,200,200)).
// A soup without extent is only centred.
void fit_into_box(TriangleSoup& soup, double size);
// The same for any vertices, given the box to fit.
void fit_into_box(std::vector<Vec3>& vertices, const Box3& box, double size);

}  // namespace convray::mesh
