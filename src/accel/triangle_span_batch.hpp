#pragma once
// Exact spans of many triangles' supports along one line at once: SIMD lanes over triangles,
// branch-free, for the line queries of SupportIndex (whose Embree callbacks only collect the
// triangles whose support box the line crosses). The same mathematics as triangle_span in
// support_shapes.hpp, the scalar twin the tests compare this with: the prism over the triangle
// (|height| <= R) joined to the three edge capsules' bodies and the three corner balls. The
// triangle's unit normal and edge lengths come from its frame (field/triangle_frame.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include "accel/support_shapes.hpp"
#include "accel/triangle_line.hpp"
#include "field/triangle.hpp"
#include "field/triangle_frame.hpp"
#include "util/simd_width.hpp"

namespace convray::accel {

class TriangleSpanBatch {
 public:
  // Gathers triangles[ids[k]] and their frames (field::triangle_frame, frames[ids[k]]) into
  // the lanes (the storage is reused from call to call).
  void gather(std::span<const field::Triangle> triangles,
              std::span<const field::TriangleFrame> frames, std::span<const uint32_t> ids);
  // spans[k] for the k-th gathered triangle; an empty support crossing gives an empty Span.
  // `direction` is of unit length.
  void compute(const Vec3& origin, const Vec3& direction, double radius);
  // The same, and each gathered triangle's terms along the line (accel/triangle_line.hpp) in
  // new rows of `table`: the k-th triangle's in the returned row + k.
  size_t compute(const Vec3& origin, const Vec3& direction, double radius,
                 TriangleLineTable& table);

  size_t size() const { return size_; }
  Span span(size_t k) const { return {enter_[k], exit_[k]}; }

 private:
  template <bool kTerms>
  void compute_lanes(const Vec3& origin, const Vec3& direction, double radius,
                     TriangleLineTable::Columns terms);

  std::vector<double> corner_[3][3];  // corner_[vertex][axis]
  // From the frames: the square roots of the triangle, made once per mesh.
  std::vector<double> normal_[3], length_[3], area_;
  std::vector<double> enter_, exit_;  // rounded up to whole SIMD widths
  size_t size_ = 0;
};

}  // namespace convray::accel
