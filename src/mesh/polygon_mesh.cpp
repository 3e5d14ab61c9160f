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

// `what` names the element ("face"), `where` says which (" (face 3)"): a function, so the text
// is only made for an error (once per face, it was a tenth of loading a large mesh).
template <typename Where>
void check_indices(std::span<const int64_t> indices, const std::string& what, Where&& where,
                   size_t vertex_count, const std::string& file) {
  for (int64_t index : indices) {
    if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
      fail(file, what + " refers to vertex " + std::to_string(index) + ", but the file has " +
                     std::to_string(vertex_count) + " vertices" + where());
  }
}

void check_face(std::span<const int64_t> face, size_t f, size_t vertex_count, const std::string& file) {
  if (face.size() < 3)
    fail(file, "face has " + std::to_string(face.size()) + " corners; at least 3 are needed" + in_face(f));
  check_indices(face, "face", [f] { return in_face(f); }, vertex_count, file);
}

bool has_repeated_vertex(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

bool has_zero_area(const Triangle& t, const std::vector<Vec3>& positions) {
  Vec3 normal = glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
  return normal == Vec3(0.0);
}

// Keeps the triangles of one face that span an area. A face none of whose triangles does is
// counted as dropped, once (a 255-corner face is one face, not its 253 triangles): for a
// repeated vertex when it names one twice, else for zero area.
void keep_proper_triangles(std::span<const Triangle> triangles, TriangleSoup& soup, LoadReport& report) {
  const size_t before = soup.triangles.size();
  bool repeated_vertex = false;
  for (const Triangle& t : triangles) {
    if (has_repeated_vertex(t)) {
      repeated_vertex = true;
    } else if (!has_zero_area(t, soup.vertices)) {
      soup.triangles.push_back(t);
    }
  }
  if (soup.triangles.size() > before) return;
  ++(repeated_vertex ? report.dropped_repeated_vertex : report.dropped_zero_area);
}

void add_triangles(const PolygonMesh& polygons, LoadedMesh& mesh, const std::string& file) {
  mesh.report.faces_read = polygons.face_count();
  mesh.soup.triangles.reserve(polygons.face_count());
  std::vector<uint32_t> corners;
  std::vector<Triangle> triangles;
  for (size_t f = 0; f < polygons.face_count(); ++f) {
    std::span<const int64_t> face = polygons.face(f);
    check_face(face, f, mesh.soup.vertices.size(), file);
    if (face.size() == 3) {
      // A triangle is itself (as triangulate_polygon would return it), without the copies.
      const Triangle triangle = {static_cast<uint32_t>(face[0]), static_cast<uint32_t>(face[1]),
                                 static_cast<uint32_t>(face[2])};
      keep_proper_triangles({&triangle, 1}, mesh.soup, mesh.report);
      continue;
    }
    corners.assign(face.begin(), face.end());
    if (corners.size() > 3) ++mesh.report.polygons_triangulated;
    triangles.clear();
    triangulate_polygon(corners, mesh.soup.vertices, triangles);
    keep_proper_triangles(triangles, mesh.soup, mesh.report);
  }
  mesh.report.triangles_kept = mesh.soup.triangles.size();
}

// Each pair of consecutive corners of a line is a segment; segments whose ends coincide
// (one index twice, or two equal positions) are dropped and counted.
void add_segments(const PolygonMesh& polygons, LoadedMesh& mesh, const std::string& file) {
  mesh.report.lines_read = polygons.lines.size();
  const std::vector<Vec3>& positions = mesh.soup.vertices;
  for (size_t l = 0; l < polygons.lines.size(); ++l) {
    std::span<const int64_t> line = polygons.lines[l];
    if (line.size() < 2)
      fail(file, "line has " + std::to_string(line.size()) + " corners; at least 2 are needed" + in_line(l));
    check_indices(line, "line", [l] { return in_line(l); }, positions.size(), file);
    for (size_t k = 0; k + 1 < line.size(); ++k) {
      const auto a = static_cast<uint32_t>(line[k]), b = static_cast<uint32_t>(line[k + 1]);
      if (positions[a] == positions[b]) {
        ++mesh.report.dropped_zero_length;
      } else {
        mesh.segments.push_back({a, b});
      }
    }
  }
  mesh.report.segments_kept = mesh.segments.size();
}

// The file's points; for a file with no faces and no lines, every vertex.
void add_points(const PolygonMesh& polygons, LoadedMesh& mesh, const std::string& file) {
  check_indices(polygons.points, "point", [] { return std::string(); }, mesh.soup.vertices.size(),
                file);
  mesh.points.assign(polygons.points.begin(), polygons.points.end());
  if (polygons.face_count() == 0 && polygons.lines.size() == 0 && polygons.points.empty()) {
    mesh.report.point_cloud = true;
    mesh.points.resize(mesh.soup.vertices.size());
    for (size_t v = 0; v < mesh.points.size(); ++v) mesh.points[v] = static_cast<uint32_t>(v);
  }
}

}  // namespace

LoadedMesh build_soup(PolygonMesh polygons, const std::string& file) {
  check_vertex_count(polygons, file);
  check_coordinates_finite(polygons, file);
  LoadedMesh mesh;
  mesh.format = polygons.format;
  mesh.soup.vertices = std::move(polygons.vertices);
  add_triangles(polygons, mesh, file);
  add_segments(polygons, mesh, file);
  add_points(polygons, mesh, file);
  return mesh;
}

}  // namespace convray::mesh
