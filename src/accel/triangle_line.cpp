#include "accel/triangle_line.hpp"

#include <algorithm>
#include <cmath>

#include "field/triangle_frame.hpp"

namespace convray::accel {

// Each step as TriangleSpanBatch rounds it (triangle_span_batch.cpp: prism, capsule_start,
// ball): the unit normal and the edges' lengths from the triangle's frame, each edge's inward
// normal n x edge scaled by the reciprocal of the edge's length.
TriangleReach triangle_reach(const Vec3& origin, const Vec3& direction,
                             const field::Triangle& triangle) {
  return triangle_reach(origin, direction, triangle, field::triangle_frame(triangle));
}

TriangleReach triangle_reach(const Vec3& origin, const Vec3& direction,
                             const field::Triangle& triangle, const field::TriangleFrame& frame) {
  const Vec3 corner[3] = {triangle.a, triangle.b, triangle.c};
  const Vec3& n = frame.normal;
  TriangleReach reach;
  reach.height[0] = glm::dot(origin - triangle.a, n);
  reach.height[1] = glm::dot(direction, n);
  reach.tilt = plane_tilt(reach.height[1]);
  double along[3];
  for (int k = 0; k < 3; ++k) {
    const Vec3& v = corner[k];
    const Vec3 edge = corner[(k + 1) % 3] - v;
    const double length = frame.length[k];
    const double inverse = 1.0 / (length > 0.0 ? length : 1.0);
    const Vec3 inward = glm::cross(n, edge);
    reach.outside[k][0] = -(glm::dot(origin - v, inward) * inverse);
    reach.outside[k][1] = -(glm::dot(direction, inward) * inverse);
    along[k] = -glm::dot(origin - v, direction);
  }
  reach.along[0] = std::min(std::min(along[0], along[1]), along[2]);
  reach.along[1] = std::max(std::max(along[0], along[1]), along[2]);
  return reach;
}

Span corners_within(const Vec3& origin, const Vec3& direction, const field::Triangle& triangle,
                    double radius) {
  Span within{-kInfinity, kInfinity};
  for (const Vec3& corner : {triangle.a, triangle.b, triangle.c}) {
    const Span ball = sphere_span(origin, direction, corner, radius);
    if (ball.empty()) return {kInfinity, -kInfinity};
    within.enter = std::max(within.enter, ball.enter);
    within.exit = std::min(within.exit, ball.exit);
  }
  return within;
}

// Room for whole 4 KiB pages of rows per column, plus the stagger (a cache line per column).
constexpr size_t kPageDoubles = 512, kStagger = 8;

size_t TriangleLineTable::grow(size_t n) {
  const size_t first = size_;
  size_ += n;
  if (size_ + kStagger > stride_) {
    const size_t rows = (std::max(size_, 2 * stride_) + kPageDoubles - 1) / kPageDoubles * kPageDoubles;
    const size_t stride = rows + kStagger;
    std::vector<double> grown(kColumns * stride);
    for (size_t c = 0; c < kColumns; ++c) {  // the rows so far, each column to its new place
      std::copy_n(buffer_.data() + c * stride_, first, grown.data() + c * stride);
    }
    buffer_.swap(grown);
    stride_ = stride;
  }
  return first;
}

TriangleLineTable::Columns TriangleLineTable::columns() {
  double* b = buffer_.data();
  const size_t s = stride_;
  return {b + kH0 * s,  b + kH1 * s,  b + kO00 * s, b + kO01 * s,         b + kO10 * s,
          b + kO11 * s, b + kO20 * s, b + kO21 * s, b + kLo * s,          b + kHi * s,
          b + kWithinEnter * s,       b + kWithinExit * s, b + kTwiceArea * s,
          b + kTilt * s};
}

}  // namespace convray::accel
