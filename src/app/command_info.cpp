#include "app/command_info.hpp"

#include <algorithm>
#include <cstdio>

#include "app/short_number.hpp"
#include "mesh/load.hpp"
#include "mesh/self_intersections.hpp"
#include "mesh/stats.hpp"
#include "util/error.hpp"

namespace convray::app {
namespace {

std::string number(double value) { return short_number(value, 6); }

std::string triple(const Vec3& v) { return number(v.x) + " " + number(v.y) + " " + number(v.z); }

void print_faces(const mesh::LoadReport& report, std::ostream& out) {
  size_t dropped = report.dropped_zero_area + report.dropped_repeated_vertex;
  out << "faces read: " << report.faces_read << "\n"
      << "polygons triangulated: " << report.polygons_triangulated << "\n"
      << "dropped faces: " << dropped << " (zero-area: " << report.dropped_zero_area
      << ", repeated-vertex: " << report.dropped_repeated_vertex << ")\n";
}

void print_topology(const mesh::MeshStats& stats, std::ostream& out) {
  out << "boundary edges: " << stats.boundary_edges << "\n"
      << "non-manifold edges: " << stats.non_manifold_edges << "\n"
      << "inconsistently oriented edges: " << stats.inconsistent_edges << "\n"
      << "connected components: " << stats.connected_components << "\n"
      << "Euler characteristic: " << stats.euler_characteristic()
      << " (V - E + F; 2 per closed sphere-like component, 2 less per handle)\n";
}

// The advice of mesh::advised_radius, with its two ingredients.
void print_radius_advice(const mesh::MeshStats& stats, std::ostream& out) {
  Vec3 size = stats.bounds.extent();
  double largest = std::max({size.x, size.y, size.z});
  double start = mesh::advised_radius(stats);
  out << "radius advice: start with R = " << number(start)
      << " (the smaller of the mean edge length, " << number(stats.mean_edge_length)
      << ", and a tenth of the largest dimension, " << number(largest)
      << "); larger radii blur the shape\n";
}

void print_report(const std::string& path, const mesh::LoadedMesh& mesh,
                  const mesh::MeshStats& stats, std::ostream& out) {
  out << "file: " << path << "\n"
      << "format: " << mesh.format << "\n"
      << "triangles: " << stats.triangles << "\n"
      << "vertices: " << stats.vertices << " (distinct positions)\n";
  print_faces(mesh.report, out);
  out << "bounding box min: " << triple(stats.bounds.lo) << "\n"
      << "bounding box max: " << triple(stats.bounds.hi) << "\n"
      << "size: " << triple(stats.bounds.extent()) << "\n"
      << "mean edge length: " << number(stats.mean_edge_length) << "\n";
  print_topology(stats, out);
  print_radius_advice(stats, out);
}

// Faces are numbered from 1 in file order among the triangles kept (polygons split into fans,
// degenerate faces dropped: the report's 'polygons triangulated' and 'dropped faces').
void print_self_intersections(const mesh::TriangleSoup& soup, std::ostream& out) {
  const mesh::SelfIntersections found = mesh::find_self_intersections(soup, 5);
  out << "self-intersecting face pairs: " << found.pairs
      << " (faces meeting beyond their shared corners, exact arithmetic)\n";
  if (found.flat_faces > 0) {
    out << "flat faces not checked: " << found.flat_faces << " (collinear corners)\n";
  }
  for (const auto& pair : found.examples) {
    out << "  faces " << pair[0] + 1 << " and " << pair[1] + 1 << " intersect\n";
  }
}

}  // namespace

int run_info(const std::string& path, bool self_intersections, std::ostream& out,
             std::ostream& err) {
  try {
    mesh::LoadedMesh mesh = mesh::load_mesh(path);
    print_report(path, mesh, mesh::compute_stats(mesh.soup), out);
    if (self_intersections) print_self_intersections(mesh.soup, out);
    return 0;
  } catch (const InputError& error) {
    err << error.what() << "\n";
    return 2;
  }
}

}  // namespace convray::app
