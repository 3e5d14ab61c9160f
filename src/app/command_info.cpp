#include "app/command_info.hpp"

#include <algorithm>
#include <cstdio>

#include "app/command_step.hpp"
#include "app/short_number.hpp"
#include "scene/mesh_skeleton.hpp"
#include "implicit/repeated_triangles.hpp"
#include "mesh/load.hpp"
#include "mesh/self_intersections.hpp"
#include "mesh/skeleton_stats.hpp"
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

void print_lines(const mesh::LoadReport& report, std::ostream& out) {
  if (report.lines_read == 0) return;
  out << "lines read: " << report.lines_read << " (polylines and edges; dropped zero-length segments: "
      << report.dropped_zero_length << ")\n";
}

void print_points(const mesh::LoadReport& report, const mesh::SkeletonStats& skeleton, std::ostream& out) {
  if (report.point_cloud) out << "point cloud: the file has no faces and no lines, so every vertex is a point\n";
  if (skeleton.points < 2) return;
  out << "mean point spacing: " << number(skeleton.mean_point_spacing)
      << " (mean distance from each point to its nearest neighbour)\n";
}

// The advice of mesh::advise_radius, with its two ingredients.
void print_radius_advice(const mesh::RadiusAdvice& advice, std::ostream& out) {
  out << "radius advice: start with R = " << number(advice.radius);
  switch (advice.basis) {
    case mesh::RadiusBasis::edges:
      out << " (the smaller of the mean edge length, " << number(advice.measure) << ", and a tenth of the largest "
          << "dimension, " << number(advice.largest) << "); larger radii blur the shape\n";
      return;
    case mesh::RadiusBasis::segments:
      out << " (the smaller of the mean segment length, " << number(advice.measure) << ", and a tenth of the "
          << "largest dimension, " << number(advice.largest) << "); larger radii thicken the tubes\n";
      return;
    case mesh::RadiusBasis::points:
      out << " (the smaller of twice the mean point spacing, " << number(advice.measure) << ", and a tenth of the "
          << "largest dimension, " << number(advice.largest) << "), so that neighbouring points merge; smaller "
          << "radii leave separate beads\n";
      return;
    case mesh::RadiusBasis::size:
      out << " (a tenth of the largest dimension, " << number(advice.largest) << ", or 1 for a single point)\n";
      return;
  }
}

void print_report(const std::string& path, const mesh::LoadedMesh& mesh, const mesh::MeshStats& stats,
                  std::ostream& out) {
  const mesh::SkeletonStats skeleton = mesh::compute_skeleton_stats(mesh);
  out << "file: " << path << "\n"
      << "format: " << mesh.format << "\n"
      << "triangles: " << stats.triangles << "\n"
      << "segments: " << skeleton.segments << "\n"
      << "points: " << skeleton.points << "\n"
      << "vertices: " << stats.vertices << " (distinct positions)\n";
  print_faces(mesh.report, out);
  if (stats.triangles > 0) {
    out << "repeated triangles: " << implicit::repeated_triangle_count(scene::soup_triangles(mesh.soup))
        << " (copies of another face's three corners; a render sums each once, times its count)\n";
  }
  print_lines(mesh.report, out);
  out << "bounding box min: " << triple(skeleton.bounds.lo) << "\n"
      << "bounding box max: " << triple(skeleton.bounds.hi) << "\n"
      << "size: " << triple(skeleton.bounds.extent()) << "\n";
  if (stats.triangles > 0) {
    out << "mean edge length: " << number(stats.mean_edge_length) << "\n";
    print_topology(stats, out);
  }
  if (skeleton.segments > 0) out << "mean segment length: " << number(skeleton.mean_segment_length) << "\n";
  print_points(mesh.report, skeleton, out);
  print_radius_advice(mesh::advise_radius(stats, skeleton), out);
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
  CommandStep step("reading " + path, kFreeMemory);
  try {
    mesh::LoadedMesh mesh = mesh::load_mesh(path);
    step.now("measuring " + path, kFreeMemory);
    print_report(path, mesh, mesh::compute_stats(mesh.soup), out);
    if (self_intersections) {
      step.now("looking for self-intersections", "leave out --self-intersections");
      print_self_intersections(mesh.soup, out);
    }
    return 0;
  } catch (const InputError& error) {
    err << error.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    return step.out_of_memory(err);
  } catch (const std::length_error&) {
    return step.out_of_memory(err);
  }
}

}  // namespace convray::app
