#pragma once
// The triangles of a loaded soup as field primitives.
#include <vector>

#include "field/triangle.hpp"
#include "mesh/soup.hpp"

namespace convray::app {

inline std::vector<field::Triangle> soup_triangles(const mesh::TriangleSoup& soup) {
  std::vector<field::Triangle> triangles;
  triangles.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles) {
    triangles.push_back({soup.vertices[t[0]], soup.vertices[t[1]], soup.vertices[t[2]]});
  }
  return triangles;
}

}  // namespace convray::app
