#pragma once
// What every per-ray user of a triangle (the SIMD field batch, the window march's curvature
// bounds) needs beyond its corners: its unit normal, the unit directions and lengths of its
// edges, and its area. Computed once per mesh (ConvolutionSurface keeps one per triangle,
// 128 bytes) instead of once per ray and triangle (their square roots and divisions:
// docs/benchmarks.md, issue 15's fifth step).
#include <array>

#include "field/triangle.hpp"

namespace convray::field {

struct TriangleFrame {
  Vec3 normal{0.0};                    // unit; zero for a zero-area or non-finite triangle
  std::array<Vec3, 3> direction{};     // of edge k, from corner k to corner k + 1, unit
  std::array<double, 3> length{};      // of edge k
  double area = 0.0;                   // half the length of (b - a) x (c - a)

  bool has_area() const { return normal != Vec3(0.0); }
};

// The frame of `t`, computed with exactly the operations TriangleBatch used per ray, so that a
// batch assigned from frames holds the same bits as one assigned from corners.
TriangleFrame triangle_frame(const Triangle& t);

}  // namespace convray::field
