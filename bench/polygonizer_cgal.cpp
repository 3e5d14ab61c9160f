// CGAL 5.5's Mesh_3 as a surface mesher of F = T: Delaunay refinement of the restricted
// surface of an implicit domain, with facet criteria only (no cell criteria: the tetrahedra
// inside are never refined, so this is a surface mesher that happens to carry a 3D
// triangulation). Mesh_3 rather than the older Surface_mesher (make_surface_mesh): Mesh_3
// is the package CGAL maintains (Surface_mesher is deprecated and gone from CGAL 6), and it
// has the manifold option and a TBB-parallel mode.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <array>
#include <chrono>
#include <functional>
#include <sstream>
#include <vector>

#include "polygonizer_eval.hpp"

namespace convray::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Domain = CGAL::Labeled_mesh_domain_3<Kernel>;
#ifdef CGAL_LINKED_WITH_TBB
using Concurrency = CGAL::Parallel_tag;
constexpr const char* kConcurrency = "Parallel_tag (TBB)";
#else
using Concurrency = CGAL::Sequential_tag;
constexpr const char* kConcurrency = "Sequential_tag";
#endif
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, Concurrency>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

}  // namespace

PolygonizerOutput polygonize_cgal(const Problem& problem) {
  const auto start = std::chrono::steady_clock::now();
  const double h = problem.cell;
  const implicit::MeshField& field = *problem.field;
  const double threshold = problem.threshold;
  // CGAL's implicit domains are negative inside: T - F.
  std::function<double(const Point&)> function = [&field, threshold](const Point& p) {
    return threshold - field.value(Vec3(p.x(), p.y(), p.z()));
  };
  // The bounding sphere must lie outside the surface: the soup's box grown by R, plus a cell.
  const Vec3 center = 0.5 * (problem.soup_bounds.lo + problem.soup_bounds.hi);
  const double radius =
      0.5 * glm::length(problem.soup_bounds.hi - problem.soup_bounds.lo) + field.radius() + h;
  // Surface points come from bisection on segments to within relative_error_bound times
  // the sphere's radius: the default 1e-3 would be a third of a cell on the dragon.
  const double relative_error = 1e-7;
  namespace params = CGAL::parameters;
  Domain domain = Domain::create_implicit_mesh_domain(
      function, Kernel::Sphere_3(Point(center.x, center.y, center.z), radius * radius),
      params::relative_error_bound = relative_error);
  // Resolution comparable with a grid of cell h: Delaunay balls of radius at most h (a
  // marching-cubes mesh at cell h has edges from 0 to h*sqrt(2)), and the facet centres
  // within h/10 of the surface.
  const double facet_size = h, facet_distance = 0.1 * h;
  Criteria criteria(params::facet_angle = 30.0, params::facet_size = facet_size,
                    params::facet_distance = facet_distance);
  const Complex complex = CGAL::make_mesh_3<Complex>(domain, criteria, params::no_perturb(),
                                                     params::no_exude(), params::manifold());

  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> faces;
  // Subdomain 1 is F > T; its facets with normals pointing out of it.
  CGAL::Mesh_3::internal::facets_in_complex_3_to_triangle_soup(complex, 1, points, faces, true,
                                                               false);
  PolygonizerOutput result;
  for (const Point& p : points) result.mesh.vertices.push_back({p.x(), p.y(), p.z()});
  for (const auto& f : faces) {
    result.mesh.triangles.push_back(
        {static_cast<uint32_t>(f[0]), static_cast<uint32_t>(f[1]), static_cast<uint32_t>(f[2])});
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream note;
  note << "Mesh_3 " << kConcurrency << ", facet_angle 30, facet_size " << facet_size
       << ", facet_distance " << facet_distance << ", manifold(), no perturb/exude, "
       << "relative_error_bound " << relative_error;
  result.note = note.str();
  return result;
}

}  // namespace convray::bench
