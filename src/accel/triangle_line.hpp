#pragma once
// What a line sees of a triangle besides its support's span: the terms the window march
// (implicit/) sets up for every triangle it reaches, made where the span is made. The exact
// spans' SIMD batch (TriangleSpanBatch) has the corners in its lanes and computes the same
// products for the prism and the corner balls; writing these terms beside the spans costs a
// few stores per lane, where the march computed them again one triangle at a time (with the
// area from the triangle's frame, a cache miss): 10 % of the soup's render, 14 % at R = 5
// (docs/benchmarks.md, sixteenth step). The scalar twins below compute
// them with the batch's operations in its order, to the bit (tests compare).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "accel/support_shapes.hpp"
#include "field/triangle.hpp"
#include "field/triangle_frame.hpp"
#include "util/math.hpp"

namespace convray::accel {

// The triangle's height above its plane and the outward distances past its three edges of
// the foot of p(t) = origin + t direction, each linear in t (its value at t = 0 and its
// slope), and the range of u.(q - origin) over its corners q. All zero where the triangle has
// no area (no plane). implicit/triangle_reach.hpp's curvature bounds read them.
struct TriangleReach {
  double height[2] = {0.0, 0.0};  // along the unit normal (b - a) x (c - a): h0 + h1 t
  double outside[3][2] = {};      // past edge k (corner k to k + 1), in the plane: o0 + o1 t
                                  // (<= 0: on the triangle's side of its line)
  double along[2] = {0.0, 0.0};   // [lo, hi]
  // 1 / sqrt(3 - 2 h1^2), h1 the slope of the height (the line's cosine to the normal): the
  // factor of the march's downward limit for the triangle's plane (implicit/triangle_reach.hpp's
  // triangle_down_limit), a square root and a division per member that the lanes make cheaply.
  double tilt = 1.0 / std::sqrt(3.0);
};

// The tilt of a line whose height above a plane has slope h1 (TriangleReach::tilt).
inline double plane_tilt(double h1) {
  return 1.0 / std::sqrt(3.0 - 2.0 * std::min(h1 * h1, 1.0));
}

// The scalar twins (direction of unit length).
// `frame`: the triangle's (field::triangle_frame), where the caller has it.
TriangleReach triangle_reach(const Vec3& origin, const Vec3& direction,
                             const field::Triangle& triangle, const field::TriangleFrame& frame);
TriangleReach triangle_reach(const Vec3& origin, const Vec3& direction,
                             const field::Triangle& triangle);
// Where all three corners lie within `radius` of p(t): the intersection of the corners' ball
// chords (empty where a corner's ball misses the line). There the whole triangle lies inside
// the kernel's ball, and its field along the line is a quartic in t.
Span corners_within(const Vec3& origin, const Vec3& direction, const field::Triangle& triangle,
                    double radius);

// Rows of those terms, one per triangle the batch handled, in columns (the batch stores
// whole SIMD widths at once). Cleared by its owner for each line.
class TriangleLineTable {
 public:
  void clear() { size_ = 0; }
  size_t size() const { return size_; }
  // Appends n rows (their values to be written) and returns the first; n whole SIMD widths.
  size_t grow(size_t n);

  TriangleReach reach(size_t row) const {  // inline: the march reads one per member
    const double* r = buffer_.data() + row;
    const size_t s = stride_;
    return {{r[kH0 * s], r[kH1 * s]},
            {{r[kO00 * s], r[kO01 * s]}, {r[kO10 * s], r[kO11 * s]}, {r[kO20 * s], r[kO21 * s]}},
            {r[kLo * s], r[kHi * s]},
            r[kTilt * s]};
  }
  Span corners_within(size_t row) const {
    return {buffer_[kWithinEnter * stride_ + row], buffer_[kWithinExit * stride_ + row]};
  }
  // |(b - a) x (c - a)|: twice the area (field::triangle_frame's, to a few ulps: the frame is
  // made with fused multiply-adds, for the field's batch).
  double twice_area(size_t row) const { return buffer_[kTwiceArea * stride_ + row]; }

  // The columns, for the batch: height, outside (edge-major), along, corners within, area,
  // tilt.
  struct Columns {
    double *h0, *h1, *o00, *o01, *o10, *o11, *o20, *o21, *lo, *hi, *within_enter, *within_exit,
        *twice_area, *tilt;
  };
  Columns columns();

 private:
  enum Column {
    kH0, kH1, kO00, kO01, kO10, kO11, kO20, kO21, kLo, kHi, kWithinEnter, kWithinExit,
    kTwiceArea, kTilt, kColumns
  };
  size_t size_ = 0;
  size_t stride_ = 0;  // from one column to the next in buffer_: room for rows, and a stagger
  // The columns one after the other, each a cache line further along a 4 KiB page than the
  // last: as separate arrays of one size they lay the same row of every column at the same
  // offset in a page, and the batch's thirteen stores per lane fought over one cache set
  // (a render's time moved by a tenth from one allocation pattern to another).
  std::vector<double> buffer_;
};

}  // namespace convray::accel
