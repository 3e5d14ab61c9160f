#pragma once
// The Cauchy surface's truncation boxes in the one hierarchy over boxes (core/bvh.hpp): which
// boxes hold a point, and which boxes a ray crosses and where it enters and leaves each. Boxes
// are closed: a point on a face is inside. The hierarchy is built over the boxes slightly
// padded (core/box.hpp's padded), so that its slab test, by reciprocals, never culls a box
// that the exact clip of the answers (clip_to_box) meets.
#include <cstdint>
#include <vector>

#include "core/bvh.hpp"
#include "core/ray.hpp"
#include "util/math.hpp"

namespace convray::implicit {

class BoxBvh {
 public:
  BoxBvh() = default;
  explicit BoxBvh(std::vector<Box3> boxes);

  const std::vector<Box3>& boxes() const { return boxes_; }
  Box3 bounds() const { return bounds_; }
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
  std::vector<Box3> boxes_;
  Box3 bounds_;
  Bvh bvh_;  // over the padded boxes
};

}  // namespace convray::implicit
