// Quality measures of bench/polygonizer_libraries: topology (mesh::compute_stats), self
// intersections (mesh::find_self_intersections, exact), accuracy against the exact field, and
// triangle shape.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mesh/distance.hpp"
#include "mesh/self_intersections.hpp"
#include "mesh/stats.hpp"
#include "polygonizer_eval.hpp"

namespace convray::bench {

namespace {

// Unsigned distance from p to the soup, exact among the triangles within R of p (the field's
// contributors); R when there are none, which a vertex near F = T never is.
double soup_distance(const implicit::MeshField& field, const Vec3& p) {
  thread_local std::vector<uint32_t> list;
  field.contributors(p, list);
  double best = field.radius();
  for (uint32_t i : list) {
    const field::Triangle& t = field.triangles()[i];
    best = std::min(best, mesh::point_triangle_distance(p, t.a, t.b, t.c));
  }
  return best;
}

}  // namespace

Quality measure_quality(const Problem& problem, const mesh::TriangleSoup& mesh) {
  Quality q;
  const mesh::MeshStats stats = mesh::compute_stats(mesh);
  q.triangles = stats.triangles;
  q.vertices = stats.vertices;
  q.boundary_edges = stats.boundary_edges;
  q.non_manifold_edges = stats.non_manifold_edges;
  q.inconsistent_edges = stats.inconsistent_edges;
  q.components = stats.connected_components;
  q.euler = stats.euler_characteristic();
  q.degenerate_triangles = stats.degenerate_triangles;
  if (mesh.triangles.empty()) return q;
  q.self_intersecting_pairs = mesh::find_self_intersections(mesh).pairs;

  const implicit::MeshField& field = *problem.field;
  const double t = problem.threshold;
  std::vector<double> vertex_error(mesh.vertices.size()), offset_error(mesh.vertices.size());
  tbb::parallel_for(size_t{0}, mesh.vertices.size(), [&](size_t v) {
    vertex_error[v] = std::abs(field.field_exact(mesh.vertices[v]).value - t) / t;
    offset_error[v] = std::abs(soup_distance(field, mesh.vertices[v]) - problem.offset);
  });
  for (size_t v = 0; v < vertex_error.size(); ++v) {
    q.max_field_error = std::max(q.max_field_error, vertex_error[v]);
    q.mean_field_error += vertex_error[v] / vertex_error.size();
    q.max_offset_error = std::max(q.max_offset_error, offset_error[v]);
    q.mean_offset_error += offset_error[v] / offset_error.size();
  }

  const size_t n = mesh.triangles.size();
  std::vector<double> min_angle(n), distance(n);
  std::vector<char> outward(n), converged(n);
  tbb::parallel_for(size_t{0}, n, [&](size_t i) {
    const auto c = mesh.corners(i);
    double smallest = 180.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e1 = c[(k + 1) % 3] - c[k], e2 = c[(k + 2) % 3] - c[k];
      const double l = glm::length(e1) * glm::length(e2);
      const double angle = l > 0 ? std::acos(std::clamp(glm::dot(e1, e2) / l, -1.0, 1.0)) : 0.0;
      smallest = std::min(smallest, angle * 180.0 / kPi);
    }
    min_angle[i] = smallest;
    // Newton steps along the gradient: x <- x - (F - T) grad / |grad|^2 converges fast from a
    // point this close to the surface; the step length sum is the distance to the foot point.
    const Vec3 centroid = (c[0] + c[1] + c[2]) / 3.0;
    Vec3 x = centroid;
    field::FieldSample s = field.field(x);
    outward[i] = glm::dot(glm::cross(c[1] - c[0], c[2] - c[0]), -s.gradient) > 0.0;
    // Steps are capped at R/4 so that a small gradient (a saddle between two sheets) cannot
    // throw the point away; a point that has not converged after 40 steps is counted apart.
    const double max_step = 0.25 * field.radius();
    int it = 0;
    for (; it < 40 && std::abs(s.value - t) > 1e-9 * t; ++it) {
      const double g2 = glm::dot(s.gradient, s.gradient);
      if (!(g2 > 0.0)) {
        it = 40;
        break;
      }
      Vec3 step = (s.value - t) / g2 * s.gradient;
      const double l = glm::length(step);
      if (l > max_step) step *= max_step / l;
      x -= step;
      s = field.field(x);
    }
    converged[i] = it < 40;
    distance[i] = glm::length(x - centroid);
  });
  q.min_angle_degrees = 180.0;
  size_t small = 0, out = 0;
  for (size_t i = 0; i < n; ++i) {
    q.min_angle_degrees = std::min(q.min_angle_degrees, min_angle[i]);
    small += min_angle[i] < 10.0;
    out += outward[i];
    if (!converged[i]) {
      ++q.unprojected_centroids;
      continue;
    }
    q.max_centroid_distance = std::max(q.max_centroid_distance, distance[i]);
    q.mean_centroid_distance += distance[i];
  }
  if (n > q.unprojected_centroids) q.mean_centroid_distance /= n - q.unprojected_centroids;
  q.small_angle_fraction = static_cast<double>(small) / n;
  q.outward_fraction = static_cast<double>(out) / n;
  return q;
}

}  // namespace convray::bench
