#include "mesh/polygon_mesh.hpp"

#include <cmath>
#include <limits>

#include "mesh/load_error.hpp"
#include "mesh/triangulate.hpp"

namespace convray::mesh {
namespace {

void check_coordinates_finite(const PolygonMesh& polygons, const std::string& file) {
  for (size_t v = 0; v < polygons.vertices.size(); ++v) {
    const Vec3& p = polygons.vertices[v];
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) continue;
    if (polygons.vertex_per_corner) fail(file, "triangle corner has a non-finite coordinate" + in_face(v / 3));
    fail(file, "vertex has a non-finite coordinate" + in_vertex(v));
  }
}

// The soup stores indices as uint32_t; more vertices than that cannot be addressed.
void check_vertex_count(const PolygonMesh& polygons, const std::string& file) {
  if (polygons.vertices.size() > std::numeric_limits<uint32_t>::max())
    fail(file, "the file has " + std::to_string(polygons.vertices.size()) +
                   " vertices, more than convray can index (4294967295)");
}

void check_face(std::span<const int64_t> face, size_t f, size_t vertex_count, const std::string& file) {
  if (face.size() < 3)
    fail(file, "face has " + std::to_string(face.size()) + " corners; at least 3 are needed" + in_face(f));
  for (int64_t index : face) {
    if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
      fail(file, "face refers to vertex " + std::to_string(index) + ", but the file has " +
                     std::to_string(vertex_count) + " vertices" + in_face(f));
  }
}

bool has_repeated_vertex(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

bool has_zero_area(const Triangle& t, const std::vector<Vec3>& positions) {
  Vec3 normal = glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
  return normal == Vec3(0.0);
}

// Keeps the triangles that span an area, and counts the others.
void keep_proper_triangles(const std::vector<Triangle>& triangles, TriangleSoup& soup, LoadReport& report) {
  for (const Triangle& t : triangles) {
    if (has_repeated_vertex(t)) {
      ++report.dropped_repeated_vertex;
    } else if (has_zero_area(t, soup.vertices)) {
      ++report.dropped_zero_area;
    } else {
      soup.triangles.push_back(t);
    }
  }
}

}  // namespace

LoadedMesh build_soup(PolygonMesh polygons, const std::string& file) {
  check_vertex_count(polygons, file);
  check_coordinates_finite(polygons, file);
  LoadedMesh mesh;
  mesh.format = polygons.format;
  mesh.soup.vertices = std::move(polygons.vertices);
  mesh.report.faces_read = polygons.face_count();
  mesh.soup.triangles.reserve(polygons.face_count());

  std::vector<uint32_t> corners;
  std::vector<Triangle> triangles;
  for (size_t f = 0; f < polygons.face_count(); ++f) {
    std::span<const int64_t> face = polygons.face(f);
    check_face(face, f, mesh.soup.vertices.size(), file);
    corners.assign(face.begin(), face.end());
    if (corners.size() > 3) ++mesh.report.polygons_triangulated;
    triangles.clear();
    triangulate_polygon(corners, mesh.soup.vertices, triangles);
    keep_proper_triangles(triangles, mesh.soup, mesh.report);
  }
  mesh.report.triangles_kept = mesh.soup.triangles.size();
  return mesh;
}

}  // namespace convray::mesh
