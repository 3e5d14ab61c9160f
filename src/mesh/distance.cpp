#include "mesh/distance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/box.hpp"
#include "core/bvh.hpp"

namespace convray::mesh {
namespace {

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::distance(p, a + t * ab);
}

// The nearest-point query over a soup's triangles, in the one hierarchy (core/bvh.hpp) built
// over their padded boxes, so that a box is never farther than rounding puts its triangles.
class TriangleTree {
 public:
  explicit TriangleTree(const TriangleSoup& soup) : soup_(soup), bvh_(padded_boxes(soup)) {}

  // Distance from p to the nearest triangle.
  double nearest(const Vec3& p) const {
    double best = INFINITY;
    bvh_.nearer_than(p, best, [&](uint32_t t, double& nearest) {
      const std::array<Vec3, 3> c = soup_.corners(t);
      nearest = std::min(nearest, point_triangle_distance(p, c[0], c[1], c[2]));
    });
    return best;
  }

 private:
  static std::vector<Box3> padded_boxes(const TriangleSoup& soup) {
    std::vector<Box3> boxes(soup.size());
    for (size_t t = 0; t < soup.size(); ++t) {
      for (const Vec3& corner : soup.corners(t)) boxes[t].extend(corner);
      boxes[t] = padded(boxes[t]);
    }
    return boxes;
  }

  const TriangleSoup& soup_;
  Bvh bvh_;
};

double triangle_area(const std::array<Vec3, 3>& c) {
  return 0.5 * glm::length(glm::cross(c[1] - c[0], c[2] - c[0]));
}

// The vertices the triangles use, each once (by index).
std::vector<Vec3> used_vertices(const TriangleSoup& soup) {
  std::vector<char> used(soup.vertices.size(), 0);
  for (const Triangle& t : soup.triangles) used[t[0]] = used[t[1]] = used[t[2]] = 1;
  std::vector<Vec3> points;
  for (size_t v = 0; v < soup.vertices.size(); ++v) {
    if (used[v]) points.push_back(soup.vertices[v]);
  }
  return points;
}

}  // namespace

double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Ericson, Real-Time Collision Detection, 5.1.5: find the Voronoi region of p (a vertex,
  // an edge or the face) from barycentric-style dot products, then project onto it.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const Vec3 normal = glm::cross(ab, ac);
  if (glm::dot(normal, normal) == 0.0) {  // a segment or a point: its sides say it all
    return std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                     point_segment_distance(p, c, a)});
  }
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return glm::distance(p, a);
  const Vec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return glm::distance(p, b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::distance(p, a + d1 / (d1 - d3) * ab);
  const Vec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return glm::distance(p, c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::distance(p, a + d2 / (d2 - d6) * ac);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    return glm::distance(p, b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b));
  }
  // Inside the face: the distance to the plane, which is exact and cheaper than projecting.
  return std::abs(glm::dot(ap, normal)) / glm::length(normal);
}

SurfaceSamples sample_surface(const TriangleSoup& soup, size_t count) {
  double total = 0.0;
  for (size_t t = 0; t < soup.size(); ++t) total += triangle_area(soup.corners(t));
  SurfaceSamples samples;
  if (!(total > 0.0)) return samples;
  for (size_t t = 0; t < soup.size(); ++t) {
    const std::array<Vec3, 3> c = soup.corners(t);
    const double area = triangle_area(c);
    if (!(area > 0.0)) continue;
    const int cuts = std::max(1, static_cast<int>(std::ceil(std::sqrt(count * area / total))));
    const double piece = area / (static_cast<double>(cuts) * cuts);
    const Vec3 u = (c[1] - c[0]) / double(cuts), v = (c[2] - c[0]) / double(cuts);
    // The cuts^2 small triangles: cuts (cuts + 1) / 2 upright ones at (i, j) with
    // i + j < cuts, centroid at (i + 1/3, j + 1/3), and the upside-down ones between them
    // (i + j < cuts - 1), centroid at (i + 2/3, j + 2/3), in units of u and v.
    for (int i = 0; i < cuts; ++i) {
      for (int j = 0; i + j < cuts; ++j) {
        samples.points.push_back(c[0] + (i + 1.0 / 3.0) * u + (j + 1.0 / 3.0) * v);
        samples.areas.push_back(piece);
        if (i + j + 1 < cuts) {
          samples.points.push_back(c[0] + (i + 2.0 / 3.0) * u + (j + 2.0 / 3.0) * v);
          samples.areas.push_back(piece);
        }
      }
    }
  }
  return samples;
}

OneSidedDistance one_sided_distance(const TriangleSoup& from, const TriangleSoup& to,
                                    const DistanceOptions& options) {
  if (from.size() == 0 || to.size() == 0) {
    throw std::invalid_argument("one_sided_distance: both soups need a triangle");
  }
  const TriangleTree tree(to);
  OneSidedDistance result;
  auto measure = [&](const Vec3& p) {
    const double d = tree.nearest(p);
    if (d > result.max) result.max = d, result.farthest = p;
    ++result.points;
    return d;
  };
  for (const Vec3& p : used_vertices(from)) measure(p);
  const SurfaceSamples samples = sample_surface(from, options.samples);
  double weighted = 0.0, area = 0.0;
  for (size_t s = 0; s < samples.points.size(); ++s) {
    weighted += samples.areas[s] * measure(samples.points[s]);
    area += samples.areas[s];
  }
  result.mean = area > 0.0 ? weighted / area : 0.0;
  return result;
}

HausdorffDistance hausdorff_distance(const TriangleSoup& a, const TriangleSoup& b,
                                     const DistanceOptions& options) {
  return {one_sided_distance(a, b, options), one_sided_distance(b, a, options)};
}

}  // namespace convray::mesh
