#pragma once
// What every per-ray user of a triangle (the SIMD field batch, the window march's curvature
// bounds, the exact spans of its support) needs beyond its corners: its unit normal, the
// lengths of its edges, and its area: the square roots of the frame. Computed once per mesh
// (ConvolutionSurface keeps one per triangle, 56 bytes) instead of once per ray and triangle
// (docs/benchmarks.md, issue 15's fifth step). The edges' unit directions, edge times
// 1 / length, are left to the batch's set_lane (a division an edge there): kept here they
// were 72 bytes a triangle, 14.6 MB of the dragon's 200,000 first touched at every start
// (issue 15's twentieth step).
#include <array>
#include <span>
#include <vector>

#include "field/triangle.hpp"

namespace convray::field {

struct TriangleFrame {
  Vec3 normal{0.0};                    // unit; zero for a zero-area or non-finite triangle
  std::array<double, 3> length{};      // of edge k, from corner k to corner k + 1 (always)
  double area = 0.0;                   // half the length of (b - a) x (c - a)

  bool has_area() const { return normal != Vec3(0.0); }
};

// The frame of `t`, computed with exactly the operations TriangleBatch used per ray, so that a
// batch assigned from frames holds the same bits as one assigned from corners.
TriangleFrame triangle_frame(const Triangle& t);
// triangle_frame of each triangle, in order.
std::vector<TriangleFrame> triangle_frames(std::span<const Triangle> triangles);

}  // namespace convray::field
