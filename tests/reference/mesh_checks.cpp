#include "reference/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>

namespace convray::reference {

bool segment_pierces_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                              const Vec3& c) {
  // Möller–Trumbore on the line p + t (q - p), then 0 < t < 1 and strictly inside barycentrics.
  constexpr double kEps = 1e-9;
  const Vec3 d = q - p, e1 = b - a, e2 = c - a;
  const Vec3 h = glm::cross(d, e2);
  const double det = glm::dot(e1, h);
  const double scale = glm::length(d) * glm::length(e1) * glm::length(e2);
  if (std::abs(det) <= 1e-12 * scale) return false;  // parallel (coplanar overlaps not checked)
  const Vec3 s = p - a;
  const double u = glm::dot(s, h) / det;
  const Vec3 qv = glm::cross(s, e1);
  const double v = glm::dot(d, qv) / det;
  const double t = glm::dot(e2, qv) / det;
  return t > kEps && t < 1.0 - kEps && u > kEps && v > kEps && u + v < 1.0 - kEps;
}

namespace {

bool boxes_overlap(const Box3& x, const Box3& y) {
  for (int axis = 0; axis < 3; ++axis) {
    if (x.hi[axis] < y.lo[axis] || y.hi[axis] < x.lo[axis]) return false;
  }
  return true;
}

// Whether triangles s and t (as corner indices) cross, given the corners they share.
bool triangles_cross(const IndexedMesh& m, const std::array<uint32_t, 3>& s,
                     const std::array<uint32_t, 3>& t) {
  int shared = 0;
  for (uint32_t i : s) shared += int(std::count(t.begin(), t.end(), i));
  if (shared >= 2) return false;
  const auto pierces = [&](const std::array<uint32_t, 3>& edge_owner,
                           const std::array<uint32_t, 3>& other) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t i = edge_owner[k], j = edge_owner[(k + 1) % 3];
      // With one shared corner, only the edge opposite it can cross the other triangle.
      const bool touches_shared =
          std::count(other.begin(), other.end(), i) || std::count(other.begin(), other.end(), j);
      if (shared == 1 && touches_shared) continue;
      if (segment_pierces_triangle(m.vertices[i], m.vertices[j], m.vertices[other[0]],
                                   m.vertices[other[1]], m.vertices[other[2]])) {
        return true;
      }
    }
    return false;
  };
  return pierces(s, t) || pierces(t, s);
}

}  // namespace

size_t count_self_intersections(const IndexedMesh& mesh) {
  const size_t n = mesh.triangles.size();
  std::vector<Box3> boxes(n);
  double largest = 0.0;
  for (size_t t = 0; t < n; ++t) {
    for (uint32_t v : mesh.triangles[t]) boxes[t].extend(mesh.vertices[v]);
    const Vec3 e = boxes[t].extent();
    largest = std::max({largest, e.x, e.y, e.z});
  }
  if (n == 0) return 0;
  // A uniform grid of cells at least as large as any triangle's box: triangles whose boxes
  // overlap have their low corners in the same or neighbouring cells.
  const double cell = std::max(largest, 1e-300);
  const Vec3 origin =
      std::accumulate(boxes.begin(), boxes.end(), Box3{}, [](Box3 all, const Box3& b) {
        all.extend(b.lo);
        return all;
      }).lo;
  std::map<std::array<int64_t, 3>, std::vector<size_t>> cells;
  const auto cell_of = [&](const Vec3& p) {
    return std::array<int64_t, 3>{int64_t((p.x - origin.x) / cell),
                                  int64_t((p.y - origin.y) / cell),
                                  int64_t((p.z - origin.z) / cell)};
  };
  for (size_t t = 0; t < n; ++t) cells[cell_of(boxes[t].lo)].push_back(t);
  size_t crossings = 0;
  for (size_t s = 0; s < n; ++s) {
    const auto home = cell_of(boxes[s].lo);
    for (int64_t dz = -1; dz <= 1; ++dz) {
      for (int64_t dy = -1; dy <= 1; ++dy) {
        for (int64_t dx = -1; dx <= 1; ++dx) {
          const auto found = cells.find({home[0] + dx, home[1] + dy, home[2] + dz});
          if (found == cells.end()) continue;
          for (size_t t : found->second) {
            if (t > s && boxes_overlap(boxes[s], boxes[t]) &&
                triangles_cross(mesh, mesh.triangles[s], mesh.triangles[t])) {
              ++crossings;
            }
          }
        }
      }
    }
  }
  return crossings;
}

double enclosed_volume(const IndexedMesh& mesh) {
  double volume = 0.0;
  for (const auto& t : mesh.triangles) {
    volume += glm::dot(mesh.vertices[t[0]], glm::cross(mesh.vertices[t[1]], mesh.vertices[t[2]]));
  }
  return volume / 6.0;
}

}  // namespace convray::reference
