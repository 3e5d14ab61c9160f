#include "mesh/procedural.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace convray::mesh {
namespace {

// Index of the vertex halfway between a and b on the unit sphere, made once per edge.
uint32_t midpoint(uint32_t a, uint32_t b, std::vector<Vec3>& unit, std::map<std::pair<uint32_t, uint32_t>, uint32_t>& cache) {
  auto key = std::minmax(a, b);
  auto [it, inserted] = cache.try_emplace(key, static_cast<uint32_t>(unit.size()));
  if (inserted) unit.push_back(glm::normalize(unit[a] + unit[b]));
  return it->second;
}

TriangleSoup unit_icosahedron() {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleSoup soup;
  soup.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : soup.vertices) p = glm::normalize(p);
  soup.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return soup;
}

}  // namespace

TriangleSoup icosphere(const Vec3& center, double radius, int subdivisions) {
  TriangleSoup soup = unit_icosahedron();
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> cache;
    std::vector<Triangle> finer;
    finer.reserve(4 * soup.size());
    for (auto [a, b, c] : soup.triangles) {
      uint32_t ab = midpoint(a, b, soup.vertices, cache);
      uint32_t bc = midpoint(b, c, soup.vertices, cache);
      uint32_t ca = midpoint(c, a, soup.vertices, cache);
      finer.insert(finer.end(), {Triangle{a, ab, ca}, Triangle{b, bc, ab}, Triangle{c, ca, bc}, Triangle{ab, bc, ca}});
    }
    soup.triangles = std::move(finer);
  }
  for (Vec3& p : soup.vertices) p = center + radius * p;
  return soup;
}

TriangleSoup torus(double major, double minor, int nu, int nv) {
  TriangleSoup soup;
  auto index = [nu, nv](int i, int j) { return static_cast<uint32_t>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i) {
    double u = 2.0 * kPi * i / nu;
    for (int j = 0; j < nv; ++j) {
      double v = 2.0 * kPi * j / nv;
      double ring = major + minor * std::cos(v);
      soup.vertices.emplace_back(ring * std::cos(u), ring * std::sin(u), minor * std::sin(v));
    }
  }
  // Going round the axis, then round the tube, turns counter-clockwise seen from outside.
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      soup.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      soup.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return soup;
}

TriangleSoup sheet_with_hole(double half_size, int cells, double hole_radius) {
  TriangleSoup soup;
  auto index = [cells](int i, int j) { return static_cast<uint32_t>(j * (cells + 1) + i); };
  auto coordinate = [half_size, cells](double i) { return -half_size + 2.0 * half_size * i / cells; };
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) soup.vertices.emplace_back(coordinate(i), coordinate(j), 0.0);
  }
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      double cx = coordinate(i + 0.5), cy = coordinate(j + 0.5);
      if (std::hypot(cx, cy) < hole_radius) continue;
      soup.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      soup.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return soup;
}

TriangleSoup flat_grid(double half_size, int cells) { return sheet_with_hole(half_size, cells, 0.0); }

}  // namespace convray::mesh
