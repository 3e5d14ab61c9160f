#pragma once
// A prebuilt, immutable Embree hierarchy over the supports of one group of triangles (one
// radius), in the triangles' own space: what SupportIndex places as an instance instead of
// rebuilding a mesh it has seen before (support_index.hpp, SupportSources::TriangleGroup).
// It keeps its triangles alive and may be shared by any number of indexes, on any threads.
// This header does not include Embree; only accel/*.cpp do.
#include <memory>
#include <span>
#include <vector>

#include "field/triangle.hpp"
#include "util/math.hpp"

namespace convray::accel {

class TriangleSupports {
 public:
  // Builds the hierarchy over the supports (radius `radius`) of `triangles`, each float box
  // grown by `margin` beyond its outward rounding: the slack the float rays of the indexes it
  // is placed in will need (see required_instance_margin in support_index.hpp).
  TriangleSupports(std::shared_ptr<const std::vector<field::Triangle>> triangles, double radius,
                   double margin);
  ~TriangleSupports();
  TriangleSupports(const TriangleSupports&) = delete;
  TriangleSupports& operator=(const TriangleSupports&) = delete;

  const std::vector<field::Triangle>& triangles() const;
  size_t size() const;
  double radius() const;
  double margin() const;
  Box3 bounds() const;          // union of the supports, in the triangles' space, no margin
  size_t memory_bytes() const;  // what Embree allocated for the hierarchy

  struct Impl;  // the Embree scene (accel/*.cpp)
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// The union of the supports (radius `radius`) of `triangles`.
Box3 triangle_supports_bounds(std::span<const field::Triangle> triangles, double radius);

}  // namespace convray::accel
