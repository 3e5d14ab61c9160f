#pragma once
// Segments and points prepared for batched field evaluation: structure-of-arrays, one SIMD
// lane per primitive, branch-free. Exact twins: segment.hpp and point.hpp.
#include <span>
#include <vector>

#include "field/sample.hpp"
#include "field/segment.hpp"

namespace convray::field {

class SegmentBatch {
 public:
  SegmentBatch() = default;
  explicit SegmentBatch(std::span<const Segment> segments);

  size_t size() const { return length_.size(); }
  // Sums of the raw fields (strength 1) of all segments at p.
  double value(const Vec3& p, double radius) const;
  FieldSample field(const Vec3& p, double radius) const;

 private:
  template <bool kGradient>
  FieldSample evaluate(const Vec3& p, double radius) const;

  std::vector<double> ax_, ay_, az_;  // start point
  std::vector<double> ux_, uy_, uz_;  // unit direction (zero for zero-length segments)
  std::vector<double> length_;
};

class PointBatch {
 public:
  PointBatch() = default;
  explicit PointBatch(std::span<const Vec3> centers);

  size_t size() const { return x_.size(); }
  double value(const Vec3& p, double radius) const;
  FieldSample field(const Vec3& p, double radius) const;

 private:
  std::vector<double> x_, y_, z_;
};

}  // namespace convray::field
