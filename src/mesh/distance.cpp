#include "mesh/distance.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace convray::mesh {
namespace {

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::distance(p, a + t * ab);
}

// Squared distance from p to a box; 0 inside.
double box_distance2(const Vec3& p, const Box3& box) {
  const Vec3 outside = glm::max(glm::max(box.lo - p, p - box.hi), Vec3(0.0));
  return glm::dot(outside, outside);
}

// A bounding-volume hierarchy over a soup's triangles, for nearest-point queries: median
// splits along the longest axis of the centroids' box, leaves of up to four triangles.
class TriangleTree {
 public:
  explicit TriangleTree(const TriangleSoup& soup) : soup_(soup), order_(soup.size()) {
    std::iota(order_.begin(), order_.end(), size_t{0});
    nodes_.reserve(2 * soup.size() / kLeafSize + 1);
    build(0, order_.size());
  }

  // Distance from p to the nearest triangle.
  double nearest(const Vec3& p) const {
    double best = INFINITY;
    // Depth-first, nearer child first, skipping boxes no nearer than the best so far.
    size_t stack[128];
    size_t depth = 0;
    stack[depth++] = 0;
    while (depth > 0) {
      const Node& node = nodes_[stack[--depth]];
      if (box_distance2(p, node.box) >= best * best) continue;
      if (node.count > 0) {
        for (size_t i = node.first; i < node.first + node.count; ++i) {
          const std::array<Vec3, 3> c = soup_.corners(order_[i]);
          best = std::min(best, point_triangle_distance(p, c[0], c[1], c[2]));
        }
        continue;
      }
      size_t near = node.first, far = node.right;
      if (box_distance2(p, nodes_[far].box) < box_distance2(p, nodes_[near].box))
        std::swap(near, far);
      stack[depth++] = far;
      stack[depth++] = near;
    }
    return best;
  }

 private:
  static constexpr size_t kLeafSize = 4;
  struct Node {
    Box3 box;
    size_t first = 0;  // leaf: first index into order_; inner node: index of the left child
    size_t count = 0;  // triangles of a leaf; 0 for an inner node
    size_t right = 0;  // inner node: index of the right child
  };

  Vec3 centroid(size_t t) const {
    const std::array<Vec3, 3> c = soup_.corners(t);
    return (c[0] + c[1] + c[2]) / 3.0;
  }

  // Builds the node for order_[begin, end) and returns its index. Median splits keep the depth
  // at log2(n / 4) + 1, well inside the query's stack.
  size_t build(size_t begin, size_t end) {
    const size_t index = nodes_.size();
    nodes_.push_back({});
    Box3 box, centres;
    for (size_t i = begin; i < end; ++i) {
      for (const Vec3& corner : soup_.corners(order_[i])) box.extend(corner);
      centres.extend(centroid(order_[i]));
    }
    if (end - begin <= kLeafSize) {
      nodes_[index] = {box, begin, end - begin, 0};
      return index;
    }
    const Vec3 extent = centres.extent();
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const size_t middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](size_t a, size_t b) { return centroid(a)[axis] < centroid(b)[axis]; });
    build(begin, middle);  // the left child is the next node
    const size_t right = build(middle, end);
    nodes_[index] = {box, index + 1, 0, right};
    return index;
  }

  const TriangleSoup& soup_;
  std::vector<size_t> order_;
  std::vector<Node> nodes_;
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
