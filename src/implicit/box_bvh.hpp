#pragma once
// A bounding-volume hierarchy over axis-aligned boxes (median split on the widest axis), for
// the Cauchy surface's truncation boxes: which boxes hold a point, and which boxes a ray
// crosses and where it enters and leaves each. Boxes are closed: a point on a face is inside.
#include <cstdint>
#include <vector>

#include "core/ray.hpp"
#include "util/math.hpp"

namespace convray::implicit {

class BoxBvh {
 public:
  BoxBvh() = default;
  explicit BoxBvh(std::vector<Box3> boxes);

  const std::vector<Box3>& boxes() const { return boxes_; }
  Box3 bounds() const { return nodes_.empty() ? Box3{} : nodes_[0].box; }
  size_t memory_bytes() const;

  // Appends the index of every box that holds p.
  void contain(const Vec3& p, std::vector<uint32_t>& out) const;

  // One box the ray crosses: its index and the part [t0, t1] of [tmin, tmax] inside it.
  struct Span {
    uint32_t id = 0;
    double t0 = 0.0, t1 = 0.0;
  };
  // Appends a Span for every box that meets the ray within [tmin, tmax] (t0 <= t1).
  void crossed(const Ray& ray, double tmin, double tmax, std::vector<Span>& out) const;

 private:
  struct Node {
    Box3 box;
    uint32_t first = 0;  // leaf: first entry in order_; inner: index of the left child
    uint32_t count = 0;  // leaf: number of boxes; inner: 0 (the right child is left + 1)
  };
  void build(uint32_t node, uint32_t begin, uint32_t end);

  std::vector<Box3> boxes_;
  std::vector<uint32_t> order_;  // box indices, grouped by leaf
  std::vector<Node> nodes_;
};

}  // namespace convray::implicit
