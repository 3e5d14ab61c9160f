// A second opinion on `convray info --self-intersections`, from an independent exact
// implementation: CGAL's Polygon_mesh_processing::self_intersections on the same file.
//   cgal_self_intersections MESH
// Prints the number of intersecting face pairs. Faces CGAL's halfedge mesh cannot hold
// (non-manifold ones, a repeated face) are left out and counted on a line of their own, so
// compare on manifold meshes. Optional target, built with polygonizer_libraries' packages.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <exception>
#include <iterator>
#include <vector>

#include "mesh/load.hpp"

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: cgal_self_intersections MESH\n");
    return 2;
  }
  try {
    const convray::mesh::TriangleSoup soup = convray::mesh::load_mesh(argv[1]).soup;
    Mesh mesh;
    std::vector<Mesh::Vertex_index> vertices;
    for (const convray::Vec3& p : soup.vertices) {
      vertices.push_back(mesh.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
    }
    size_t rejected = 0;
    for (const convray::mesh::Triangle& t : soup.triangles) {
      rejected += mesh.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]) == Mesh::null_face();
    }
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
    CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(pairs));
    std::printf("CGAL self-intersecting face pairs: %zu\n", pairs.size());
    if (rejected > 0) std::printf("faces CGAL's mesh could not hold (left out): %zu\n", rejected);
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 2;
  }
}
