// Quality measures of bench/polygonizer_libraries: topology (mesh::compute_stats), self
// intersections, accuracy against the exact field, and triangle shape.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "mesh/stats.hpp"
#include "polygonizer_eval.hpp"

namespace convray::bench {

namespace {

// --- Möller's triangle-triangle test ------------------------------------------------------

// Orientation of c relative to the directed line a->b in 2D: > 0 left, < 0 right, 0 on it.
double orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Closed segments p0p1 and q0q1 in 2D: touching counts.
bool segments_meet(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const double d1 = orient2d(q0, q1, p0), d2 = orient2d(q0, q1, p1);
  const double d3 = orient2d(p0, p1, q0), d4 = orient2d(p0, p1, q1);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  auto on_segment = [](const Vec2& a, const Vec2& b, const Vec2& c) {  // c collinear with ab
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
           c.y <= std::max(a.y, b.y);
  };
  return (d1 == 0 && on_segment(q0, q1, p0)) || (d2 == 0 && on_segment(q0, q1, p1)) ||
         (d3 == 0 && on_segment(p0, p1, q0)) || (d4 == 0 && on_segment(p0, p1, q1));
}

bool point_in_triangle_2d(const Vec2& p, const Vec2 t[3]) {
  const double a = orient2d(t[0], t[1], p), b = orient2d(t[1], t[2], p),
               c = orient2d(t[2], t[0], p);
  return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
}

// Both triangles lie in the plane of normal n: project on the coordinate plane where n is
// largest and test edges, then containment.
bool coplanar_triangles_intersect(const Vec3& n, const Vec3 a[3], const Vec3 b[3]) {
  const Vec3 m = glm::abs(n);
  const int drop = (m.x >= m.y && m.x >= m.z) ? 0 : (m.y >= m.z ? 1 : 2);
  const int i0 = drop == 0 ? 1 : 0, i1 = drop == 2 ? 1 : 2;
  Vec2 p[3], q[3];
  for (int k = 0; k < 3; ++k) p[k] = {a[k][i0], a[k][i1]}, q[k] = {b[k][i0], b[k][i1]};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (segments_meet(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3])) return true;
    }
  }
  return point_in_triangle_2d(p[0], q) || point_in_triangle_2d(q[0], p);
}

// The interval of the intersection line L covered by one triangle, as in Möller's
// NoDivTriTriIsect: vp are the vertices' projections on L, d their distances to the other
// triangle's plane. Returns false when the triangles are coplanar.
bool line_interval(const double vp[3], const double d[3], double& a, double& b, double& c,
                   double& x0, double& x1) {
  auto pick = [&](int i, int j, int k) {  // i alone on its side
    a = vp[i], b = (vp[j] - vp[i]) * d[i], c = (vp[k] - vp[i]) * d[i];
    x0 = d[i] - d[j], x1 = d[i] - d[k];
  };
  if (d[0] * d[1] > 0)
    pick(2, 0, 1);
  else if (d[0] * d[2] > 0)
    pick(1, 0, 2);
  else if (d[1] * d[2] > 0 || d[0] != 0)
    pick(0, 1, 2);
  else if (d[1] != 0)
    pick(1, 0, 2);
  else if (d[2] != 0)
    pick(2, 0, 1);
  else
    return false;
  return true;
}

// Signed distances of t's corners to the plane (n, p0), flushed to 0 within `eps` so that
// a corner on the plane is treated as on it (Möller's epsilon test, scaled to the input).
void plane_distances(const Vec3& n, const Vec3& p0, const Vec3 t[3], double eps, double d[3]) {
  for (int k = 0; k < 3; ++k) {
    d[k] = glm::dot(n, t[k] - p0);
    if (std::abs(d[k]) < eps) d[k] = 0.0;
  }
}

}  // namespace

bool triangles_intersect(const Vec3 v[3], const Vec3 u[3]) {
  const Vec3 n1 = glm::cross(v[1] - v[0], v[2] - v[0]);
  const Vec3 n2 = glm::cross(u[1] - u[0], u[2] - u[0]);
  const double l1 = glm::length(n1), l2 = glm::length(n2);
  if (l1 == 0.0 || l2 == 0.0) return false;  // degenerate: counted separately by stats
  double scale = 0.0;
  for (int k = 0; k < 3; ++k) {
    scale =
        std::max({scale, glm::length(v[k] - v[(k + 1) % 3]), glm::length(u[k] - u[(k + 1) % 3])});
  }
  const double eps = 1e-12 * scale;
  double du[3], dv[3];
  plane_distances(n1 / l1, v[0], u, eps, du);  // u's corners against v's plane
  if (du[0] * du[1] > 0 && du[0] * du[2] > 0) return false;
  plane_distances(n2 / l2, u[0], v, eps, dv);
  if (dv[0] * dv[1] > 0 && dv[0] * dv[2] > 0) return false;

  const Vec3 dir = glm::abs(glm::cross(n1, n2));
  const int axis = (dir.x >= dir.y && dir.x >= dir.z) ? 0 : (dir.y >= dir.z ? 1 : 2);
  const double vp[3] = {v[0][axis], v[1][axis], v[2][axis]};
  const double up[3] = {u[0][axis], u[1][axis], u[2][axis]};
  double a, b, c, x0, x1, d, e, f, y0, y1;
  if (!line_interval(vp, dv, a, b, c, x0, x1)) return coplanar_triangles_intersect(n1, v, u);
  if (!line_interval(up, du, d, e, f, y0, y1)) return coplanar_triangles_intersect(n1, v, u);
  const double xx = x0 * x1, yy = y0 * y1, xxyy = xx * yy;
  double i1[2] = {a * xxyy + b * x1 * yy, a * xxyy + c * x0 * yy};
  double i2[2] = {d * xxyy + e * xx * y1, d * xxyy + f * xx * y0};
  if (i1[0] > i1[1]) std::swap(i1[0], i1[1]);
  if (i2[0] > i2[1]) std::swap(i2[0], i2[1]);
  return !(i1[1] < i2[0] || i2[1] < i1[0]);
}

namespace {

// Welded vertex ids: equal positions get equal ids, so "share a vertex" means share a point.
std::vector<uint32_t> weld(const mesh::TriangleSoup& mesh) {
  std::vector<uint32_t> order(mesh.vertices.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  auto less = [&](uint32_t a, uint32_t b) {
    const Vec3 &p = mesh.vertices[a], &q = mesh.vertices[b];
    return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.z < q.z);
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<uint32_t> id(order.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const bool same = i > 0 && mesh.vertices[order[i]] == mesh.vertices[order[i - 1]];
    id[order[i]] = same ? id[order[i - 1]] : order[i];
  }
  return id;
}

struct CellKey {
  static uint64_t of(int64_t x, int64_t y, int64_t z) {
    return (static_cast<uint64_t>(x & 0x1FFFFF) << 42) |
           (static_cast<uint64_t>(y & 0x1FFFFF) << 21) | static_cast<uint64_t>(z & 0x1FFFFF);
  }
};

// Distance from p to the triangle abc: Ericson's closest point by Voronoi regions.
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return glm::length(ap);
  const Vec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return glm::length(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + d1 / (d1 - d3) * ab));
  const Vec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return glm::length(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + d2 / (d2 - d6) * ac));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return glm::length(p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b)));
  }
  const double denom = 1.0 / (va + vb + vc);
  return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

// Unsigned distance from p to the soup, exact among the triangles within R of p (the field's
// contributors); R when there are none, which a vertex near F = T never is.
double soup_distance(const implicit::MeshField& field, const Vec3& p) {
  thread_local std::vector<uint32_t> list;
  field.contributors(p, list);
  double best = field.radius();
  for (uint32_t i : list) {
    const field::Triangle& t = field.triangles()[i];
    best = std::min(best, point_triangle_distance(p, t.a, t.b, t.c));
  }
  return best;
}

}  // namespace

size_t count_self_intersections(const mesh::TriangleSoup& mesh) {
  const size_t n = mesh.triangles.size();
  if (n < 2) return 0;
  const std::vector<uint32_t> id = weld(mesh);
  std::vector<Box3> boxes(n);
  double edge_sum = 0.0;
  for (size_t t = 0; t < n; ++t) {
    const auto c = mesh.corners(t);
    for (const Vec3& p : c) boxes[t].extend(p);
    edge_sum += glm::length(c[1] - c[0]) + glm::length(c[2] - c[1]) + glm::length(c[0] - c[2]);
  }
  // Cells of about two mean edge lengths: a few triangles per cell, each in a few cells.
  const double cell = std::max(2.0 * edge_sum / (3.0 * n), 1e-12);
  const Vec3 origin = mesh.bounds().lo;
  auto cell_of = [&](const Vec3& p) { return glm::i64vec3(glm::floor((p - origin) / cell)); };
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
  for (uint32_t t = 0; t < n; ++t) {
    const glm::i64vec3 lo = cell_of(boxes[t].lo), hi = cell_of(boxes[t].hi);
    for (int64_t x = lo.x; x <= hi.x; ++x) {
      for (int64_t y = lo.y; y <= hi.y; ++y) {
        for (int64_t z = lo.z; z <= hi.z; ++z) cells[CellKey::of(x, y, z)].push_back(t);
      }
    }
  }
  std::vector<const std::vector<uint32_t>*> lists;
  std::vector<uint64_t> keys;
  for (const auto& [key, list] : cells) lists.push_back(&list), keys.push_back(key);
  std::vector<size_t> found(lists.size(), 0);
  tbb::parallel_for(size_t{0}, lists.size(), [&](size_t c) {
    const std::vector<uint32_t>& list = *lists[c];
    for (size_t i = 0; i < list.size(); ++i) {
      for (size_t j = i + 1; j < list.size(); ++j) {
        const uint32_t s = list[i], t = list[j];
        const auto& ts = mesh.triangles[s];
        const auto& tt = mesh.triangles[t];
        bool shared = false;
        for (int a = 0; a < 3; ++a) {
          for (int b = 0; b < 3; ++b) shared |= id[ts[a]] == id[tt[b]];
        }
        if (shared) continue;
        const Vec3 lo = glm::max(boxes[s].lo, boxes[t].lo), hi = glm::min(boxes[s].hi, boxes[t].hi);
        if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) continue;
        // Test each pair once: in the cell holding the low corner of the boxes' overlap.
        const glm::i64vec3 home = cell_of(lo);
        if (CellKey::of(home.x, home.y, home.z) != keys[c]) continue;
        const auto cs = mesh.corners(s), ct = mesh.corners(t);
        if (triangles_intersect(cs.data(), ct.data())) ++found[c];
      }
    }
  });
  size_t total = 0;
  for (size_t f : found) total += f;
  return total;
}

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
  q.self_intersecting_pairs = count_self_intersections(mesh);

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
