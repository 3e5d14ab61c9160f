#include "accel/triangle_span_batch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace convray::accel {
namespace {

// Plain doubles, so that the lane loop vectorizes after inlining.
struct P {
  double x, y, z;
};
[[gnu::always_inline]] inline P sub(P a, P b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
[[gnu::always_inline]] inline P add(P a, P b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
[[gnu::always_inline]] inline P mul(P a, double s) { return {a.x * s, a.y * s, a.z * s}; }
[[gnu::always_inline]] inline double dot(P a, P b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
[[gnu::always_inline]] inline P cross(P a, P b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// An interval being joined; empty when !(enter <= exit). Every condition below is
// a single comparison inside a select: the vectorizer turns those into blends, but not bools
// combined with & or stored.
struct Lane {
  double enter, exit;
};

[[gnu::always_inline]] inline double least(double a, double b) { return b < a ? b : a; }
[[gnu::always_inline]] inline double most(double a, double b) { return b > a ? b : a; }

// 1 / x, with 1 for x = 0 (whose callers select another answer).
[[gnu::always_inline]] inline double reciprocal(double x) { return 1.0 / (x != 0.0 ? x : 1.0); }

// Adds a piece's bounds to the union's (+inf and -inf: no bound from the piece).
[[gnu::always_inline]] inline Lane join(Lane piece, Lane span) {
  return {least(span.enter, piece.enter), most(span.exit, piece.exit)};
}

// A corner's ball, and how far along the line the corner lies (u.(corner - origin)).
struct Ball {
  Lane span;
  double along;
};
[[gnu::always_inline]] inline Ball ball(P o, P d, P center, double r2) {
  const P w = sub(o, center);
  const double tc = -dot(w, d);
  const P closest = add(w, mul(d, tc));
  const double q2 = dot(closest, closest);
  const double half = std::sqrt(q2 <= r2 ? r2 - q2 : 0.0);
  return {{q2 <= r2 ? tc - half : kInfinity, q2 <= r2 ? tc + half : -kInfinity}, tc};
}

// Where the line crosses the edge's capsule body (points within R of the edge's line whose
// projection lies on the edge), as the support needs it (support_shapes.cpp's
// add_capsule_body): an end of the infinite cylinder's chord counts only where it projects
// onto the edge; elsewhere the body's end lies on an end disk, inside the corner's ball, whose
// span the support joins anyway. No clips against the end planes, so no division by the
// line's slope along the edge. In two stages: up to the divisions, then from them. The loop
// runs the first stage for all three edges before the second: each body is a chain of a
// square root, a division and another square root, and one edge after the other the chains
// did not overlap within the processor's reordering window.
struct CapsuleStart {
  P dp, wp;
  double length, inv_length, dw, ww, dp2, inv_dp2;
};
// `length`: the edge's, from the triangle's frame.
[[gnu::always_inline]] inline CapsuleStart capsule_start(P o, P d, P a, P b, double length) {
  CapsuleStart c;
  const P axis = sub(b, a);
  c.length = length;
  c.inv_length = 1.0 / (c.length > 0.0 ? c.length : 1.0);
  const P u = mul(axis, c.inv_length);
  const P w = sub(o, a);
  c.dw = dot(d, u);
  c.ww = dot(w, u);
  c.dp = sub(d, mul(u, c.dw));
  c.wp = sub(w, mul(u, c.ww));
  c.dp2 = dot(c.dp, c.dp);
  c.inv_dp2 = reciprocal(c.dp2);
  return c;
}
[[gnu::always_inline]] inline Lane capsule_end(const CapsuleStart& c, double r2) {
  const double tc = -dot(c.wp, c.dp) * c.inv_dp2;
  const P closest = add(c.wp, mul(c.dp, tc));
  const double q2 = dot(closest, closest);
  const double half = std::sqrt(q2 <= r2 ? (r2 - q2) * c.inv_dp2 : 0.0);
  const double enter = tc - half, exit = tc + half;
  const double along_enter = c.ww + enter * c.dw, along_exit = c.ww + exit * c.dw;
  // A line parallel to the edge (dp2 = 0), a line too far from it, or no edge: nothing the
  // balls do not hold.
  const double reach = c.dp2 > 0.0 && c.length > 0.0 ? r2 - q2 : -1.0;
  const double hold_enter = reach >= 0.0 ? least(along_enter, c.length - along_enter) : -1.0;
  const double hold_exit = reach >= 0.0 ? least(along_exit, c.length - along_exit) : -1.0;
  return {hold_enter >= 0.0 ? enter : kInfinity, hold_exit >= 0.0 ? exit : -kInfinity};
}

// The prism over the triangle, |height| <= R (none for a triangle without area: its frame's
// normal is zero), in two stages: the line's height above the plane and its distances into
// the three edges' lines (g0 + t g1 >= 0 inside; the edges' inward normals n x edge are not
// of unit length), which TriangleLineTable keeps as well, then its faces (prism below).
struct PrismStart {
  double has_area, h0, h1;  // has_area > 0 where the frame has a normal
  double g0[3], g1[3];
};
[[gnu::always_inline]] inline PrismStart prism_start(P o, P d, P a, P b, P c, P n) {
  PrismStart p;
  p.has_area = dot(n, n);
  p.h0 = dot(sub(o, a), n);
  p.h1 = dot(d, n);
  // Written out: the vectorizer takes no inner loops.
  const P in_ab = cross(n, sub(b, a)), in_bc = cross(n, sub(c, b)), in_ca = cross(n, sub(a, c));
  p.g0[0] = dot(sub(o, a), in_ab);
  p.g1[0] = dot(d, in_ab);
  p.g0[1] = dot(sub(o, b), in_bc);
  p.g1[1] = dot(d, in_bc);
  p.g0[2] = dot(sub(o, c), in_ca);
  p.g1[2] = dot(d, in_ca);
  return p;
}
// Where the line crosses the prism's two faces |height| = R, each counted only where it lies
// over the triangle (support_shapes.cpp's add_prism_faces): elsewhere the prism's end is on
// a side face, whose every point is within R of its edge, inside the edge's capsule. A line
// parallel to the plane (h1 = 0) meets the prism through side faces only.
[[gnu::always_inline]] inline double over_triangle(const PrismStart& p, double t) {
  return least(least(p.g0[0] + t * p.g1[0], p.g0[1] + t * p.g1[1]), p.g0[2] + t * p.g1[2]);
}
[[gnu::always_inline]] inline Lane prism(const PrismStart& p, double radius) {
  const double inv_h1 = reciprocal(p.h1);
  const double top = (radius - p.h0) * inv_h1, bottom = -(radius + p.h0) * inv_h1;
  const double enter = least(top, bottom), exit = most(top, bottom);
  const double crossed = p.has_area > 0.0 && p.h1 != 0.0 ? 1.0 : -1.0;
  const double hold_enter = crossed > 0.0 ? over_triangle(p, enter) : -1.0;
  const double hold_exit = crossed > 0.0 ? over_triangle(p, exit) : -1.0;
  return {hold_enter >= 0.0 ? enter : kInfinity, hold_exit >= 0.0 ? exit : -kInfinity};
}

}  // namespace

void TriangleSpanBatch::gather(std::span<const field::Triangle> triangles,
                               std::span<const field::TriangleFrame> frames,
                               std::span<const uint32_t> ids) {
  const size_t n = ids.size();
  // Whole SIMD widths, the last triangle repeated: compute() then has no scalar remainder,
  // which cost about as much as the vector loop on a line's few candidates.
  const size_t lanes = whole_simd_widths(n);
  for (auto& vertex : corner_) {
    for (auto& axis : vertex) axis.resize(lanes);
  }
  for (auto& column : normal_) column.resize(lanes);
  for (auto& column : length_) column.resize(lanes);
  area_.resize(lanes);
  size_ = n;
  enter_.resize(lanes);
  exit_.resize(lanes);
  for (size_t k = 0; k < lanes; ++k) {
    const uint32_t id = ids[std::min(k, n - 1)];
    const field::Triangle& t = triangles[id];
    const Vec3* v[3] = {&t.a, &t.b, &t.c};
    for (int i = 0; i < 3; ++i) {
      corner_[i][0][k] = v[i]->x;
      corner_[i][1][k] = v[i]->y;
      corner_[i][2][k] = v[i]->z;
    }
    const field::TriangleFrame& f = frames[id];
    for (int axis = 0; axis < 3; ++axis) normal_[axis][k] = f.normal[axis];
    for (int edge = 0; edge < 3; ++edge) length_[edge][k] = f.length[edge];
    area_[k] = f.area;
  }
}

template <bool kTerms>
void TriangleSpanBatch::compute_lanes(const Vec3& origin, const Vec3& direction, double radius,
                                      TriangleLineTable::Columns terms) {
  const P o{origin.x, origin.y, origin.z}, d{direction.x, direction.y, direction.z};
  const double r2 = radius * radius;
  // Named pointers: the vectorizer does not see through an array of them.
  const double *ax = corner_[0][0].data(), *ay = corner_[0][1].data(), *az = corner_[0][2].data();
  const double *bx = corner_[1][0].data(), *by = corner_[1][1].data(), *bz = corner_[1][2].data();
  const double *cx = corner_[2][0].data(), *cy = corner_[2][1].data(), *cz = corner_[2][2].data();
  const double *nx = normal_[0].data(), *ny = normal_[1].data(), *nz = normal_[2].data();
  const double *lab = length_[0].data(), *lbc = length_[1].data(), *lca = length_[2].data();
  const double* area = area_.data();
  double* enter = enter_.data();
  double* exit = exit_.data();
  const size_t n = enter_.size();  // whole SIMD widths (gather)
#pragma GCC ivdep  // (omp simd would not vectorize the P aggregates with GCC 12)
  for (size_t k = 0; k < n; ++k) {
    const P a{ax[k], ay[k], az[k]}, b{bx[k], by[k], bz[k]}, e{cx[k], cy[k], cz[k]};
    // Each piece's bounds, joined bound by bound: a piece may give an end without the other.
    Lane span{kInfinity, -kInfinity};
    const PrismStart p = prism_start(o, d, a, b, e, {nx[k], ny[k], nz[k]});
    span = join(prism(p, radius), span);
    const CapsuleStart ab = capsule_start(o, d, a, b, lab[k]),
                       be = capsule_start(o, d, b, e, lbc[k]),
                       ea = capsule_start(o, d, e, a, lca[k]);
    // The balls' own square roots meanwhile (joined in the scalar twin's order after).
    const Ball ball_a = ball(o, d, a, r2), ball_b = ball(o, d, b, r2), ball_e = ball(o, d, e, r2);
    span = join(capsule_end(ab, r2), span);
    span = join(capsule_end(be, r2), span);
    span = join(capsule_end(ea, r2), span);
    span = join(ball_a.span, span);
    span = join(ball_b.span, span);
    span = join(ball_e.span, span);
    enter[k] = span.enter;
    exit[k] = span.exit;
    if constexpr (kTerms) {  // accel::triangle_reach and corners_within, in the same order
      terms.h0[k] = p.h0;
      terms.h1[k] = p.h1;
      terms.o00[k] = -(p.g0[0] * ab.inv_length);
      terms.o01[k] = -(p.g1[0] * ab.inv_length);
      terms.o10[k] = -(p.g0[1] * be.inv_length);
      terms.o11[k] = -(p.g1[1] * be.inv_length);
      terms.o20[k] = -(p.g0[2] * ea.inv_length);
      terms.o21[k] = -(p.g1[2] * ea.inv_length);
      terms.lo[k] = least(least(ball_a.along, ball_b.along), ball_e.along);
      terms.hi[k] = most(most(ball_a.along, ball_b.along), ball_e.along);
      terms.within_enter[k] = most(most(ball_a.span.enter, ball_b.span.enter), ball_e.span.enter);
      terms.within_exit[k] = least(least(ball_a.span.exit, ball_b.span.exit), ball_e.span.exit);
      terms.twice_area[k] = p.has_area > 0.0 ? 2.0 * area[k] : 0.0;
      terms.tilt[k] = plane_tilt(p.h1);
    }
  }
}

void TriangleSpanBatch::compute(const Vec3& origin, const Vec3& direction, double radius) {
  compute_lanes<false>(origin, direction, radius, {});
}

size_t TriangleSpanBatch::compute(const Vec3& origin, const Vec3& direction, double radius,
                                  TriangleLineTable& table) {
  const size_t first = table.grow(enter_.size());
  TriangleLineTable::Columns c = table.columns();
  for (double** column : {&c.h0, &c.h1, &c.o00, &c.o01, &c.o10, &c.o11, &c.o20, &c.o21, &c.lo,
                          &c.hi, &c.within_enter, &c.within_exit, &c.twice_area, &c.tilt}) {
    *column += first;
  }
  compute_lanes<true>(origin, direction, radius, c);
  return first;
}

}  // namespace convray::accel
