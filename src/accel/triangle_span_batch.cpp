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

// An interval being narrowed or joined; empty when !(enter <= exit). Every condition below is
// a single comparison inside a select: the vectorizer turns those into blends, but not bools
// combined with & or stored.
struct Lane {
  double enter, exit;
};

[[gnu::always_inline]] inline double least(double a, double b) { return b < a ? b : a; }
[[gnu::always_inline]] inline double most(double a, double b) { return b > a ? b : a; }

// Any empty interval as (+inf, -inf), which least/most then join as nothing.
[[gnu::always_inline]] inline Lane normal(Lane s) {
  return {s.enter <= s.exit ? s.enter : kInfinity, s.enter <= s.exit ? s.exit : -kInfinity};
}

// Narrows `span` to where g0 + t g1 >= 0, t = -g0 / g1 given (support_shapes.cpp's
// clip_half_space_at; g1 = 0 ignores t): clips against parallel planes share one reciprocal.
[[gnu::always_inline]] inline Lane clip_at(double g0, double g1, double t, Lane span) {
  const double lower = g1 > 0.0 ? t : -kInfinity;  // the bound t gives, if any
  const double upper = g1 < 0.0 ? t : kInfinity;
  const double parallel_gap = g1 == 0.0 ? g0 : 0.0;  // < 0: the line is wholly outside
  return {most(most(span.enter, lower), parallel_gap < 0.0 ? kInfinity : -kInfinity),
          least(span.exit, upper)};
}

// 1 / x, with 1 for x = 0 (whose clips ignore t).
[[gnu::always_inline]] inline double reciprocal(double x) { return 1.0 / (x != 0.0 ? x : 1.0); }

// Narrows `span` to where g0 + t g1 >= 0 (support_shapes.cpp's clip_half_space).
[[gnu::always_inline]] inline Lane clip(double g0, double g1, Lane span) {
  return clip_at(g0, g1, -g0 * reciprocal(g1), span);
}

// Adds a normalized piece to the union.
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

// Points within R of the edge's line whose projection lies on the edge (support_shapes.cpp's
// capsule_body_span), in two stages: up to the divisions, then from them. The loop runs the
// first stage for all three edges before the second: each body is a chain of a square root,
// two divisions and another square root, and one edge after the other the chains did not
// overlap within the processor's reordering window.
struct CapsuleStart {
  P dp, wp;
  double length, inv_length, dw, ww, dp2, inv_dp2, inv_dw;
};
[[gnu::always_inline]] inline CapsuleStart capsule_start(P o, P d, P a, P b) {
  CapsuleStart c;
  const P axis = sub(b, a);
  c.length = std::sqrt(dot(axis, axis));
  c.inv_length = 1.0 / (c.length > 0.0 ? c.length : 1.0);
  const P u = mul(axis, c.inv_length);
  const P w = sub(o, a);
  c.dw = dot(d, u);
  c.ww = dot(w, u);
  c.dp = sub(d, mul(u, c.dw));
  c.wp = sub(w, mul(u, c.ww));
  c.dp2 = dot(c.dp, c.dp);
  c.inv_dp2 = reciprocal(c.dp2);
  c.inv_dw = reciprocal(c.dw);
  return c;
}
[[gnu::always_inline]] inline Lane capsule_end(const CapsuleStart& c, double r2) {
  const double tc = -dot(c.wp, c.dp) * c.inv_dp2;
  const P closest = add(c.wp, mul(c.dp, tc));
  // Parallel to the axis (dp2 = 0): the whole line, or nothing, by its distance to the axis.
  const double q2 = c.dp2 > 0.0 ? dot(closest, closest) : dot(c.wp, c.wp);
  const double half = std::sqrt(q2 <= r2 ? (r2 - q2) * c.inv_dp2 : 0.0);
  Lane span{c.dp2 > 0.0 ? tc - half : -kInfinity, c.dp2 > 0.0 ? tc + half : kInfinity};
  span = clip_at(c.ww, c.dw, -c.ww * c.inv_dw, span);
  span = clip_at(c.length - c.ww, -c.dw, (c.length - c.ww) * c.inv_dw, span);
  const double miss = q2 <= r2 ? c.length : 0.0;  // 0: too far from the axis, or no edge
  return normal({miss > 0.0 ? span.enter : kInfinity, miss > 0.0 ? span.exit : -kInfinity});
}

// The prism over the triangle, |height| <= R (empty for a zero-area triangle), in two
// stages: the line's height above the plane and its distances into the three edges' lines
// (g0 + t g1 >= 0 inside; the edges' inward normals n x edge are not of unit length), which
// TriangleLineTable keeps as well, then the clips.
struct PrismStart {
  double n_length, h0, h1;
  double g0[3], g1[3];
};
[[gnu::always_inline]] inline PrismStart prism_start(P o, P d, P a, P b, P c) {
  PrismStart p;
  const P n0 = cross(sub(b, a), sub(c, a));
  p.n_length = std::sqrt(dot(n0, n0));
  const P n = mul(n0, 1.0 / (p.n_length > 0.0 ? p.n_length : 1.0));
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
[[gnu::always_inline]] inline Lane prism(const PrismStart& p, double radius) {
  Lane span{-kInfinity, kInfinity};
  const double inv_h1 = reciprocal(p.h1);
  span = clip_at(radius - p.h0, -p.h1, (radius - p.h0) * inv_h1, span);
  span = clip_at(radius + p.h0, p.h1, -(radius + p.h0) * inv_h1, span);
  span = clip(p.g0[0], p.g1[0], span);
  span = clip(p.g0[1], p.g1[1], span);
  span = clip(p.g0[2], p.g1[2], span);
  return normal({p.n_length > 0.0 ? span.enter : kInfinity,
                 p.n_length > 0.0 ? span.exit : -kInfinity});
}

}  // namespace

void TriangleSpanBatch::gather(std::span<const field::Triangle> triangles,
                               std::span<const uint32_t> ids) {
  const size_t n = ids.size();
  // Whole SIMD widths, the last triangle repeated: compute() then has no scalar remainder,
  // which cost about as much as the vector loop on a line's few candidates.
  const size_t lanes = whole_simd_widths(n);
  for (auto& vertex : corner_) {
    for (auto& axis : vertex) axis.resize(lanes);
  }
  size_ = n;
  enter_.resize(lanes);
  exit_.resize(lanes);
  for (size_t k = 0; k < lanes; ++k) {
    const field::Triangle& t = triangles[ids[std::min(k, n - 1)]];
    const Vec3* v[3] = {&t.a, &t.b, &t.c};
    for (int i = 0; i < 3; ++i) {
      corner_[i][0][k] = v[i]->x;
      corner_[i][1][k] = v[i]->y;
      corner_[i][2][k] = v[i]->z;
    }
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
  double* enter = enter_.data();
  double* exit = exit_.data();
  const size_t n = enter_.size();  // whole SIMD widths (gather)
#pragma GCC ivdep  // (omp simd would not vectorize the P aggregates with GCC 12)
  for (size_t k = 0; k < n; ++k) {
    const P a{ax[k], ay[k], az[k]}, b{bx[k], by[k], bz[k]}, e{cx[k], cy[k], cz[k]};
    Lane span{kInfinity, -kInfinity};
    const PrismStart p = prism_start(o, d, a, b, e);
    span = join(prism(p, radius), span);
    const CapsuleStart ab = capsule_start(o, d, a, b), be = capsule_start(o, d, b, e),
                       ea = capsule_start(o, d, e, a);
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
      terms.twice_area[k] = p.n_length;
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
