#pragma once
// The vertex blob of bench/table1.sh as data: one blob sphere component per distinct vertex
// of a mesh fitted into a box, and the threshold that puts the blob's surface near offset D
// from the mesh. bench/vertex_blob writes it as a POV-Ray scene; bench/vertex_blob_render
// traces the same components with convray, so both programs see the same blob.
//
// Geometry. The mesh is transformed as `convray quick --fit-box` does: a uniform scale so the
// largest extent of its bounding box is the box size, and the box centred at the origin.
//
// Threshold. A flat sheet of sphere components, rho per unit area, has the field
// rho (pi/3) R^2 (1 - h^2/R^2)^3 at height h (the plane formula of DESIGN.md section 4, since
// the sphere component is the same quartic kernel). With rho = vertices / surface area, the
// threshold rho (pi/3) R^2 (1 - D^2/R^2)^3 puts the blob's surface near offset D from the
// mesh, as `--offset D` does for the convolution surface.
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/soup.hpp"
#include "util/math.hpp"

namespace convray::bench {

struct VertexBlob {
  std::vector<Vec3> centres;  // fitted positions, one sphere component each
  double scale = 1.0;         // of the fit-box transform
  double area = 0.0;          // surface area of the fitted mesh
  double rho = 0.0;           // components per unit area
  double threshold = 0.0;     // for the surface near offset D
};

// Distinct positions of the vertices that triangles use, in the order of first use.
inline std::vector<Vec3> used_positions(const mesh::TriangleSoup& soup) {
  std::vector<Vec3> positions;
  positions.reserve(soup.vertices.size());
  std::vector<char> seen(soup.vertices.size(), 0);
  for (const auto& tri : soup.triangles) {
    for (uint32_t index : tri) {
      if (!seen[index]) positions.push_back(soup.vertices[index]);
      seen[index] = 1;
    }
  }
  // Two indices may share a position (the soup promises no welding): one component each.
  auto less = [](const Vec3& a, const Vec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  };
  std::vector<Vec3> sorted = positions;
  std::sort(sorted.begin(), sorted.end(), less);
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) return positions;
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  return sorted;
}

// The blob of `soup` fitted into a box of size `fit_box`, radius R, surface near offset D.
// Throws std::runtime_error when the mesh has no extent.
inline VertexBlob make_vertex_blob(const mesh::TriangleSoup& soup, double fit_box, double radius,
                                   double offset) {
  const Box3 box = soup.bounds();
  const Vec3 extent = box.extent();
  const double largest = std::max({extent.x, extent.y, extent.z});
  if (!(largest > 0.0)) throw std::runtime_error("the mesh has no extent");
  VertexBlob blob;
  blob.scale = fit_box / largest;
  const Vec3 centre = 0.5 * (box.lo + box.hi);
  auto fit = [&](const Vec3& p) { return (p - centre) * blob.scale; };

  blob.centres = used_positions(soup);
  for (Vec3& c : blob.centres) c = fit(c);
  for (size_t t = 0; t < soup.size(); ++t) {
    const auto [a, b, c] = soup.corners(t);
    blob.area += 0.5 * glm::length(glm::cross(fit(b) - fit(a), fit(c) - fit(a)));
  }
  // Flat-sheet threshold at height D (see the top of this file).
  blob.rho = double(blob.centres.size()) / blob.area;
  const double q = 1.0 - (offset * offset) / (radius * radius);
  blob.threshold = blob.rho * (kPi / 3.0) * radius * radius * q * q * q;
  return blob;
}

}  // namespace convray::bench
