#include "polygonize/outer_shells.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace convray::polygonize {

namespace {

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

struct Shell {
  std::vector<uint32_t> triangles;
  Box3 bounds;
  double volume = 0.0;  // signed: positive for an outward-facing closed shell
};

bool contains(const Box3& outer, const Box3& inner) {
  return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
         outer.hi.x >= inner.hi.x && outer.hi.y >= inner.hi.y && outer.hi.z >= inner.hi.z;
}

std::vector<Shell> make_shells(const mesh::TriangleSoup& soup, std::vector<uint32_t>& component) {
  std::vector<Shell> shells(triangle_components(soup, component));
  for (size_t t = 0; t < soup.triangles.size(); ++t) {
    Shell& shell = shells[component[t]];
    shell.triangles.push_back(uint32_t(t));
    const auto [a, b, c] = soup.corners(t);
    for (const Vec3& p : {a, b, c}) shell.bounds.extend(p);
    shell.volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return shells;
}

}  // namespace

size_t triangle_components(const mesh::TriangleSoup& soup, std::vector<uint32_t>& component) {
  std::vector<uint32_t> parent(soup.vertices.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (const mesh::Triangle& t : soup.triangles) {
    for (int e = 1; e < 3; ++e) {
      const uint32_t a = find_root(parent, t[0]), b = find_root(parent, t[e]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  // Number the components in the order their first triangle appears.
  std::vector<uint32_t> number(soup.vertices.size(), UINT32_MAX);
  size_t count = 0;
  component.resize(soup.triangles.size());
  for (size_t t = 0; t < soup.triangles.size(); ++t) {
    uint32_t& n = number[find_root(parent, soup.triangles[t][0])];
    if (n == UINT32_MAX) n = uint32_t(count++);
    component[t] = n;
  }
  return count;
}

double winding_number(const mesh::TriangleSoup& soup, const std::vector<uint32_t>& triangles,
                      const Vec3& p) {
  double total = 0.0;
  for (uint32_t t : triangles) {
    const auto [a0, b0, c0] = soup.corners(t);
    const Vec3 a = a0 - p, b = b0 - p, c = c0 - p;
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double numerator = glm::dot(a, glm::cross(b, c));
    const double denominator =
        la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * kPi);
}

size_t keep_outer_shells(SurfaceMesh& mesh) {
  std::vector<uint32_t> component;  // per triangle
  const std::vector<Shell> shells = make_shells(mesh.soup, component);
  std::vector<char> keep(shells.size(), 0);
  tbb::parallel_for(size_t(0), shells.size(), [&](size_t k) {
    const Shell& shell = shells[k];
    if (!(shell.volume > 0.0)) return;  // a hollow's inner wall faces inwards
    const Vec3 probe = mesh.soup.vertices[mesh.soup.triangles[shell.triangles[0]][0]];
    for (size_t c = 0; c < shells.size(); ++c) {
      if (c == k || !contains(shells[c].bounds, shell.bounds)) continue;
      if (std::abs(winding_number(mesh.soup, shells[c].triangles, probe)) > 0.5) return;
    }
    keep[k] = 1;
  });

  // Rebuild the mesh from the kept shells, vertices renumbered in their old order.
  SurfaceMesh kept;
  std::vector<uint32_t> new_index(mesh.soup.vertices.size(), UINT32_MAX);
  std::vector<mesh::Triangle> triangles;
  for (size_t t = 0; t < mesh.soup.triangles.size(); ++t) {
    if (keep[component[t]]) triangles.push_back(mesh.soup.triangles[t]);
  }
  for (mesh::Triangle& t : triangles) {
    for (uint32_t& v : t) new_index[v] = 0;
  }
  for (size_t v = 0; v < new_index.size(); ++v) {
    if (new_index[v] == UINT32_MAX) continue;
    new_index[v] = uint32_t(kept.soup.vertices.size());
    kept.soup.vertices.push_back(mesh.soup.vertices[v]);
    if (!mesh.normals.empty()) kept.normals.push_back(mesh.normals[v]);
  }
  for (mesh::Triangle& t : triangles) {
    for (uint32_t& v : t) v = new_index[v];
  }
  kept.soup.triangles = std::move(triangles);
  mesh = std::move(kept);
  return size_t(std::count(keep.begin(), keep.end(), char(1)));
}

}  // namespace convray::polygonize
