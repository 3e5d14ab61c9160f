#pragma once
// The one bounding volume hierarchy over boxes (mesh triangles, a world's objects, a CSG's
// children, the Cauchy surface's truncation boxes), built with binned surface-area heuristic
// splits. Traversal visits the primitives
// of the leaves whose boxes the ray meets, nearer child first, and lets a closest-hit query
// narrow the ray as it goes; the point query visits the primitives whose leaves hold a point
// (CSG's inside tests). The slow exact twin is a loop over every primitive; tests compare.
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/box.hpp"
#include "core/ray.hpp"

namespace convray {

class Bvh {
 public:
  Bvh() = default;
  // Boxes must be non-empty and finite.
  explicit Bvh(std::span<const Box3> boxes, int max_leaf_size = 4);

  bool empty() const { return nodes_.empty(); }
  Box3 bounds() const { return empty() ? Box3{} : nodes_.front().box; }
  size_t node_count() const { return nodes_.size(); }
  size_t memory_bytes() const {
    return nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(uint32_t);
  }

  // Calls visit(primitive, tmax) for every primitive of every leaf whose box meets the ray
  // within [tmin, tmax]; visit may lower tmax (double&) to prune what follows.
  template <class Visit>
  void traverse(const Ray& ray, double tmin, double& tmax, Visit&& visit) const;

  // Calls visit(primitive) for every primitive of every leaf whose box contains p (callers
  // test the primitive's own box) until visit returns true; returns whether one did.
  template <class Visit>
  bool any_at(const Vec3& p, Visit&& visit) const;

  // Calls visit(primitive, best) for every primitive of every leaf whose box is nearer to p
  // than `best` (a distance), nearer child first; visit may lower best (double&) to prune what
  // follows. A nearest-point query: boxes must hold their primitives, padded for rounding.
  template <class Visit>
  void nearer_than(const Vec3& p, double& best, Visit&& visit) const;

 private:
  struct Node {
    Box3 box;
    uint32_t offset = 0;  // leaf: first entry of order_; interior: index of the second child
    uint16_t count = 0;   // leaf: its primitives; 0: interior (the first child follows it)
    uint8_t axis = 0;     // interior: the split axis
  };
  struct Slabs;  // the ray's per-axis reciprocal directions

  // The depth-first walk of the queries: a node is entered where enter(node) holds; a leaf's
  // primitives go to visit(primitive), which ends the walk by returning true (and walk returns
  // true); first_child_first(index, node) orders an interior node's children.
  template <class Enter, class VisitLeaf, class FirstChildFirst>
  bool walk(Enter&& enter, VisitLeaf&& visit, FirstChildFirst&& first_child_first) const;

  void build(std::span<const Box3> boxes, std::vector<Vec3>& centroids, uint32_t node,
             uint32_t begin, uint32_t end, int max_leaf_size, int depth);
  uint32_t split(std::span<const Box3> boxes, const std::vector<Vec3>& centroids,
                 const Box3& bounds, uint32_t begin, uint32_t end, int& axis);

  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;
};

// Whether the ray meets `box` within [tmin, tmax], using the reciprocal direction.
inline bool ray_meets_box(const Vec3& origin, const Vec3& inverse_direction, const Box3& box,
                          double tmin, double tmax) {
  for (int axis = 0; axis < 3; ++axis) {
    const double inverse = inverse_direction[axis];
    if (std::isinf(inverse)) {
      // Parallel to the slab: inside it everywhere or nowhere (avoids 0 * inf).
      if (origin[axis] < box.lo[axis] || origin[axis] > box.hi[axis]) return false;
      continue;
    }
    double t0 = (box.lo[axis] - origin[axis]) * inverse;
    double t1 = (box.hi[axis] - origin[axis]) * inverse;
    if (t0 > t1) std::swap(t0, t1);
    tmin = t0 > tmin ? t0 : tmin;
    tmax = t1 < tmax ? t1 : tmax;
    if (tmin > tmax) return false;
  }
  return true;
}

template <class Enter, class VisitLeaf, class FirstChildFirst>
bool Bvh::walk(Enter&& enter, VisitLeaf&& visit, FirstChildFirst&& first_child_first) const {
  if (nodes_.empty()) return false;
  uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const Node& node = nodes_[index];
    if (!enter(node)) continue;
    if (node.count > 0) {
      for (uint32_t i = node.offset; i < node.offset + node.count; ++i) {
        if (visit(order_[i])) return true;
      }
      continue;
    }
    // The child to visit first goes on the stack last. The first child follows its parent.
    const bool first_first = first_child_first(index, node);
    stack[top++] = first_first ? node.offset : index + 1;
    stack[top++] = first_first ? index + 1 : node.offset;
  }
  return false;
}

template <class Visit>
void Bvh::traverse(const Ray& ray, double tmin, double& tmax, Visit&& visit) const {
  const Vec3 inverse = 1.0 / ray.direction;
  walk([&](const Node& node) { return ray_meets_box(ray.origin, inverse, node.box, tmin, tmax); },
       [&](uint32_t primitive) { return visit(primitive, tmax), false; },
       // Nearer child first: the first child holds the lower side of the split axis.
       [&](uint32_t, const Node& node) { return !(ray.direction[node.axis] < 0.0); });
}

template <class Visit>
bool Bvh::any_at(const Vec3& p, Visit&& visit) const {
  return walk([&](const Node& node) { return contains(node.box, p); },
              [&](uint32_t primitive) { return bool(visit(primitive)); },
              [](uint32_t, const Node&) { return true; });
}

// Squared distance from p to `box`; 0 inside.
inline double box_distance2(const Vec3& p, const Box3& box) {
  const Vec3 outside = glm::max(glm::max(box.lo - p, p - box.hi), Vec3(0.0));
  return glm::dot(outside, outside);
}

template <class Visit>
void Bvh::nearer_than(const Vec3& p, double& best, Visit&& visit) const {
  walk([&](const Node& node) { return box_distance2(p, node.box) < best * best; },
       [&](uint32_t primitive) { return visit(primitive, best), false; },
       // Nearer child first.
       [&](uint32_t index, const Node& node) {
         return !(box_distance2(p, nodes_[node.offset].box) <
                  box_distance2(p, nodes_[index + 1].box));
       });
}

}  // namespace convray
