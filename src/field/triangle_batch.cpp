#include "field/triangle_batch.hpp"

#include <algorithm>
#include <cmath>

#include "field/pie_angles.hpp"

// glibc's libmvec provides SIMD variants of atan2 (_ZGVdN4vv_atan2, _ZGVeN8vv_atan2, ...);
// declaring the simd attribute lets the vectorizer call them from the pie-slice loop. This
// file is compiled with -fno-math-errno so atan2 counts as a pure function.
extern "C" double atan2(double, double) noexcept __attribute__((simd("notinbranch")));

namespace convray::field {

struct TriangleBatch::Accumulator {
  double value = 0.0;
  Vec3 gradient{0.0};
  double* per_triangle = nullptr;  // when set, each triangle's value lands here
};

TriangleBatch::TriangleBatch(std::span<const Triangle> triangles) { assign(triangles); }

TriangleBatch::TriangleBatch(std::span<const Triangle> triangles, std::span<const double> weights) {
  assign(triangles);
  for (size_t i = 0; i < size_ && i < weights.size(); ++i) weight_[i] *= weights[i];
}

void TriangleBatch::assign(std::span<const Triangle> triangles) {
  resize(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) set_lane(i, triangles[i], triangle_frame(triangles[i]));
}

// Every lane is then written whole by set_lane: no fill first (the batches of the window
// march are reassigned for every ray, and filling 34 arrays was 2 % of a render).
// The arrays are rounded up to whole SIMD widths: the loops read the lanes past size_ (and
// mask them out); they hold zeros or an earlier triangle, finite either way.
void TriangleBatch::resize(size_t n) {
  size_ = n;
  // One more width: a range of lanes may start anywhere (value_of_range) and is read in
  // whole widths from there.
  const size_t padded = whole_simd_widths(n) + kSimdWidth;
  for (auto* v : {&nx_, &ny_, &nz_, &weight_}) v->resize(padded);
  for (EdgeArrays& e : edges_) {
    for (auto* v : {&e.vx, &e.vy, &e.vz, &e.ux, &e.uy, &e.uz, &e.mx, &e.my, &e.mz, &e.length}) {
      v->resize(padded);
    }
  }
}

// Zero-area triangles get all-zero lanes (no NaN) and weight 0.
void TriangleBatch::set_lane(size_t i, const Triangle& triangle, const TriangleFrame& frame) {
  const bool area = frame.has_area();
  const Vec3 v[3] = {triangle.a, triangle.b, triangle.c};
  const Vec3 normal = area ? frame.normal : Vec3(0.0);
  nx_[i] = normal.x, ny_[i] = normal.y, nz_[i] = normal.z;
  weight_[i] = area ? 1.0 : 0.0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 corner = area ? v[k] : Vec3(0.0);
    // The edge's unit direction (triangle_frame.hpp: the frame keeps only its length).
    // One division, then products: three divisions an edge were a quarter of this function.
    const Vec3 u = area ? (v[(k + 1) % 3] - v[k]) * (1.0 / frame.length[k]) : Vec3(0.0);
    const Vec3 m = glm::cross(u, normal);
    EdgeArrays& e = edges_[k];
    e.vx[i] = corner.x, e.vy[i] = corner.y, e.vz[i] = corner.z;
    e.ux[i] = u.x, e.uy[i] = u.y, e.uz[i] = u.z;
    e.mx[i] = m.x, e.my[i] = m.y, e.mz[i] = m.z;
    e.length[i] = area ? frame.length[k] : 0.0;
  }
}

namespace detail {

constexpr size_t kChunk = 64;
// Every loop runs over whole SIMD widths (see Listed below). For the atan2 loop: a chunk of 7
// lanes otherwise made one AVX2, one SSE and one scalar call of libmvec's and libm's atan2,
// each about as dear as the 4-wide one (7.5 % of a render of the dragon at R = 1).
static_assert(kChunk % kSimdWidth == 0);

// What phase 1 leaves for each lane of a chunk; phase 2 adds the pie-slice angles.
struct ChunkState {
  double inside[kChunk];        // Σ edges of the inside-the-disk parts (times 6R^4)
  double inside_dr0[kChunk];    // their derivative with respect to r0^2
  double gx[kChunk], gy[kChunk], gz[kChunk];  // in-plane gradient, all but nothing from θ
  double pie_y[3][kChunk], pie_x[3][kChunk];  // per edge: θ = atan2(pie_y, pie_x)
  double r0sq[kChunk], h[kChunk], scale[kChunk];
  double pie_scale;  // 1 / R^4: brings the pies' components near 1 before they multiply
  double nx[kChunk], ny[kChunk], nz[kChunk];
  int64_t touches[kChunk], o_inside[kChunk];  // 0 or 1 (64-bit: see Listed below)
};

// Raw pointers to one edge's arrays, so the vectorizer sees plain strided loads.
struct EdgeView {
  const double *vx, *vy, *vz, *ux, *uy, *uz, *mx, *my, *mz, *length;
};

// Per-lane partial results of one edge (see triangle.cpp for the mathematics).
struct EdgeTerm {
  double inside = 0.0, inside_dr0 = 0.0, pie_y = 0.0, pie_x = 0.0;
  double gx = 0.0, gy = 0.0, gz = 0.0;
  double corner_dist2 = 0.0;  // |V - P|^2 of the edge's start corner
  bool touches = false, o_outside = false;
};

// kWhollyInside: the caller knows the triangle lies inside the support sphere, so nothing is
// clipped and there are no pie slices (the common case for large radii).
template <bool kGradient, bool kWhollyInside>
[[gnu::always_inline]] inline EdgeTerm edge_term(const EdgeView& e, size_t i, const Vec3& p,
                                                 double r0sq, double r6) {
  EdgeTerm out;
  const double rx = e.vx[i] - p.x, ry = e.vy[i] - p.y, rz = e.vz[i] - p.z;
  out.corner_dist2 = rx * rx + ry * ry + rz * rz;
  const double d = rx * e.mx[i] + ry * e.my[i] + rz * e.mz[i];
  const double sa = rx * e.ux[i] + ry * e.uy[i] + rz * e.uz[i];
  const double sb = sa + e.length[i];
  const double d2 = d * d;
  const double w2 = r0sq - d2;
  const double w = kWhollyInside ? 0.0 : std::sqrt(w2 > 0.0 ? w2 : 0.0);
  const double s1 = kWhollyInside ? sa : std::max(sa, -w);
  const double s2_clip = kWhollyInside ? sb : std::min(sb, w);
  const bool has_inside = kWhollyInside || s1 < s2_clip;
  const double s2 = has_inside ? s2_clip : s1;
  out.touches = has_inside;
  out.o_outside = d < 0.0;
  const double c1 = 3.0 * r0sq * (r0sq - d2) + d2 * d2;
  const double c3 = r0sq - (2.0 / 3.0) * d2;
  const double s1_2 = s1 * s1, s2_2 = s2 * s2;
  // poly = G(s2) - G(s1) with G(s) = c1 s - c3 s^3 + s^5/5, in Horner form.
  const double poly = s2 * (c1 + s2_2 * (0.2 * s2_2 - c3)) - s1 * (c1 + s1_2 * (0.2 * s1_2 - c3));
  const double delta1 = s2 - s1;
  const double delta3 = kGradient ? s2 * s2_2 - s1 * s1_2 : 0.0;
  // Mask, don't trust s1 == s2 to give 0: with FMA contraction G(s) - G(s) leaves a residue.
  out.inside = has_inside ? d * poly : 0.0;
  if constexpr (kWhollyInside) {
    if constexpr (kGradient) {
      const double dd = poly + d * ((-6.0 * r0sq * d + 4.0 * d2 * d) * delta1 + (4.0 / 3.0) * d * delta3);
      const double ds = d * (3.0 * c3 * (s1_2 - s2_2) + s2_2 * s2_2 - s1_2 * s1_2);
      out.inside_dr0 = d * ((6.0 * r0sq - 3.0 * d2) * delta1 - delta3);
      out.gx = -(dd * e.mx[i] + ds * e.ux[i]);
      out.gy = -(dd * e.my[i] + ds * e.uy[i]);
      out.gz = -(dd * e.mz[i] + ds * e.uz[i]);
    }
    return out;
  }
  // Pie pieces [a1, b1] left of -w and [a2, b2] right of +w (empty ones have a == b); their
  // angles add without wrapping since together they subtend less than π.
  const double a1 = std::min(sa, -w), b1 = std::min(sb, -w);
  const double a2 = std::max(sa, w), b2 = std::max(sb, w);
  const double y1 = d * (b1 - a1), x1 = d2 + a1 * b1;
  const double y2 = d * (b2 - a2), x2 = d2 + a2 * b2;
  out.pie_y = y1 * x2 + y2 * x1;
  out.pie_x = x1 * x2 - y1 * y2;
  if constexpr (kGradient) {
    // ∂/∂d and ∂/∂s (s_begin and s_end move together); the ±w bounds are constants (the
    // kernel vanishes with zero slope there). d and s move with P as -m and -u.
    double dd = has_inside ? poly + d * ((-6.0 * r0sq * d + 4.0 * d2 * d) * delta1 +
                                         (4.0 / 3.0) * d * delta3)
                           : 0.0;
    double ds = 0.0;
    // A corner exactly on the circle still moves with P (see triangle.cpp): >= and <=.
    ds -= (has_inside & (sa >= -w)) ? d * (c1 - 3.0 * c3 * s1_2 + s1_2 * s1_2) : 0.0;
    ds += (has_inside & (sb <= w)) ? d * (c1 - 3.0 * c3 * s2_2 + s2_2 * s2_2) : 0.0;
    out.inside_dr0 = has_inside ? d * ((6.0 * r0sq - 3.0 * d2) * delta1 - delta3) : 0.0;
    // Subtended angle of [a, b]: ∂θ/∂a = -d/(d²+a²), ∂θ/∂b = d/(d²+b²), ∂θ/∂d = a/(d²+a²) - b/(d²+b²).
    // Divide unconditionally by a safe denominator: a conditional division would keep the
    // loop scalar (it might trap), and the vectorizer is the point of this file.
    const auto ratio = [](double num, double den) {
      const bool ok = den > 0.0;
      return (ok ? num : 0.0) / (ok ? den : 1.0);
    };
    const double da1 = d2 + a1 * a1, db1 = d2 + b1 * b1;
    const double da2 = d2 + a2 * a2, db2 = d2 + b2 * b2;
    const double pie_dd = ratio(a1, da1) - ratio(b1, db1) + ratio(a2, da2) - ratio(b2, db2);
    double pie_ds = 0.0;
    // The corner starts pie 1 when left of -w, pie 2 when at or right of +w; it ends pie 2
    // when right of +w, pie 1 when at or left of -w.
    pie_ds -= ((sa < -w) | (sa >= w)) ? ratio(d, d2 + sa * sa) : 0.0;
    pie_ds += ((sb > w) | (sb <= -w)) ? ratio(d, d2 + sb * sb) : 0.0;
    dd += r6 * pie_dd;
    ds += r6 * pie_ds;
    out.gx = -(dd * e.mx[i] + ds * e.ux[i]);
    out.gy = -(dd * e.my[i] + ds * e.uy[i]);
    out.gz = -(dd * e.mz[i] + ds * e.uz[i]);
  }
  return out;
}

}  // namespace detail

using detail::ChunkState;
using detail::EdgeTerm;
using detail::EdgeView;
using detail::kChunk;

namespace {
// The lanes a call sums: all of the batch's in order (the arrays are padded to whole SIMD
// widths, see resize), or those listed, copied a chunk at a time with the last lane repeated
// up to a whole SIMD width (ListedChunk). Every loop then runs on whole widths and masks the
// extra lanes out (their scale and weight are 0): a scalar remainder of up to three lanes
// cost about as much as the vector loop on the window march's few lanes per chunk. The lists
// and flags are 64-bit: a 32-bit type in a loop made GCC pick 8 lanes, and run any chunk of
// fewer than 8 scalar.
// `weight(i)`: what the lane's weight is multiplied by in this call (1, or a range's mask).
struct Contiguous {
  size_t operator()(size_t t) const { return t; }
  double weight(size_t) const { return 1.0; }
};
struct Listed {
  const uint64_t* list;
  size_t operator()(size_t t) const { return list[t]; }
  double weight(size_t) const { return 1.0; }
};
// A range of lanes read in place, each counted or not by its mask (1 or 0): plain loads
// where a list needs a gather per array (vgatherqpd: about half the time of a listed chunk).
struct Masked {
  const double* mask;  // indexed by lane
  size_t first;
  size_t operator()(size_t t) const { return t; }
  double weight(size_t i) const { return mask[i]; }
};
struct ListedChunk {
  uint64_t ids[kChunk];
};
Contiguous chunk_lanes(Contiguous index, size_t, size_t, ListedChunk&) { return index; }
Masked chunk_lanes(Masked index, size_t, size_t, ListedChunk&) { return index; }
// Listed lanes from `list` (32-bit, as callers keep them), the chunk from `base`.
Listed chunk_lanes(const uint32_t* list, size_t base, size_t lanes, ListedChunk& chunk) {
  for (size_t t = 0; t < lanes; ++t) chunk.ids[t] = list[base + t];
  for (size_t t = lanes; t < whole_simd_widths(lanes); ++t) chunk.ids[t] = chunk.ids[lanes - 1];
  return Listed{chunk.ids};
}
// Where the chunk's lanes start for its index: listed chunks are copied from 0.
size_t chunk_base(Contiguous, size_t base) { return base; }
size_t chunk_base(Masked index, size_t base) { return index.first + base; }
size_t chunk_base(const uint32_t*, size_t) { return 0; }
}  // namespace

// Returns whether any lane has a pie slice, i.e. whether phase 2 needs its atan2.
template <bool kGradient, class Index>
bool TriangleBatch::phase_one(const Vec3& p, double r2, double inv_norm, size_t base,
                              size_t lanes, Index index, const EdgeView* views,
                              ChunkState& st) const {
  const double *nxs = nx_.data(), *nys = ny_.data(), *nzs = nz_.data(), *ws = weight_.data();
  const EdgeView v0 = views[0], v1 = views[1], v2 = views[2];  // locals: contiguous loads
  int64_t any_pie = 0;
#pragma omp simd reduction(| : any_pie)
  for (size_t t = 0; t < whole_simd_widths(lanes); ++t) {
    const size_t i = index(base + t);
    // Every load unconditional: a load under a condition (ws[i] inside the select) needs a
    // masked gather, which GCC does not emulate, and the whole loop then stayed scalar.
    const double nx = nxs[i], ny = nys[i], nz = nzs[i], weight = ws[i] * index.weight(i);
    const double h = (p.x - v0.vx[i]) * nx + (p.y - v0.vy[i]) * ny + (p.z - v0.vz[i]) * nz;
    const double r0sq_raw = r2 - h * h;
    const bool in_range = r0sq_raw > 0.0;
    const double r0sq = in_range ? r0sq_raw : 0.0;
    const double r6 = r0sq * r0sq * r0sq;
    const EdgeTerm e0 = detail::edge_term<kGradient, false>(v0, i, p, r0sq, r6);
    const EdgeTerm e1 = detail::edge_term<kGradient, false>(v1, i, p, r0sq, r6);
    const EdgeTerm e2 = detail::edge_term<kGradient, false>(v2, i, p, r0sq, r6);
    st.inside[t] = e0.inside + e1.inside + e2.inside;
    st.inside_dr0[t] = e0.inside_dr0 + e1.inside_dr0 + e2.inside_dr0;
    st.gx[t] = e0.gx + e1.gx + e2.gx;
    st.gy[t] = e0.gy + e1.gy + e2.gy;
    st.gz[t] = e0.gz + e1.gz + e2.gz;
    st.pie_y[0][t] = e0.pie_y, st.pie_y[1][t] = e1.pie_y, st.pie_y[2][t] = e2.pie_y;
    st.pie_x[0][t] = e0.pie_x, st.pie_x[1][t] = e1.pie_x, st.pie_x[2][t] = e2.pie_x;
    st.r0sq[t] = r0sq, st.h[t] = h;
    st.nx[t] = nx, st.ny[t] = ny, st.nz[t] = nz;
    st.scale[t] = in_range && t < lanes ? weight * inv_norm : 0.0;
    st.touches[t] = e0.touches | e1.touches | e2.touches;
    st.o_inside[t] = !(e0.o_outside | e1.o_outside | e2.o_outside);
    // Lanes that count only: a masked one need not cost the atan2 pass.
    any_pie |= int64_t(in_range) & int64_t(weight != 0.0) & int64_t(t < lanes) & st.touches[t] &
               (int64_t(e0.pie_y != 0.0) | int64_t(e1.pie_y != 0.0) | int64_t(e2.pie_y != 0.0));
  }
  return any_pie != 0;
}

// Whether every corner of the chunk's triangles lies within R of p: a cheap look before the
// lean path, which would otherwise compute every edge term to find out (the window march
// hands over mostly clipped triangles, its wholly inside ones being summed as quartics).
template <class Index>
bool TriangleBatch::corners_within(const Vec3& p, double r2, size_t base, size_t lanes,
                                   Index index, const EdgeView* views) const {
  const EdgeView v0 = views[0], v1 = views[1], v2 = views[2];
  int64_t outside = 0;
#pragma omp simd reduction(| : outside)
  for (size_t t = 0; t < whole_simd_widths(lanes); ++t) {
    const size_t i = index(base + t);
    auto beyond = [&](const EdgeView& v) {
      const double dx = v.vx[i] - p.x, dy = v.vy[i] - p.y, dz = v.vz[i] - p.z;
      return int64_t(dx * dx + dy * dy + dz * dz >= r2);
    };
    outside |= int64_t(t < lanes) & int64_t(index.weight(i) != 0.0) &
               (beyond(v0) | beyond(v1) | beyond(v2));
  }
  return outside == 0;
}

// The lean path, tried optimistically: assuming every triangle of the chunk lies inside the
// support sphere, nothing is clipped and each lane's value is its three inside parts. The
// same pass checks the assumption (every corner within R); if it fails, nothing is added
// and the caller takes the general path for this chunk.
template <bool kGradient, class Index>
bool TriangleBatch::accumulate_wholly_inside(const Vec3& p, double r2, double inv_norm,
                                             size_t base, size_t lanes, Index index,
                                             const EdgeView* views, Accumulator& acc) const {
  const double *nxs = nx_.data(), *nys = ny_.data(), *nzs = nz_.data(), *ws = weight_.data();
  const EdgeView v0 = views[0], v1 = views[1], v2 = views[2];  // locals: contiguous loads
  double sum = 0.0, sgx = 0.0, sgy = 0.0, sgz = 0.0;
  int64_t outside = 0;
#pragma omp simd reduction(+ : sum, sgx, sgy, sgz) reduction(| : outside)
  for (size_t t = 0; t < whole_simd_widths(lanes); ++t) {
    const size_t i = index(base + t);
    const double nx = nxs[i], ny = nys[i], nz = nzs[i], weight = ws[i] * index.weight(i);
    const double h = (p.x - v0.vx[i]) * nx + (p.y - v0.vy[i]) * ny + (p.z - v0.vz[i]) * nz;
    const double r0sq = r2 - h * h;
    const EdgeTerm e0 = detail::edge_term<kGradient, true>(v0, i, p, r0sq, 0.0);
    const EdgeTerm e1 = detail::edge_term<kGradient, true>(v1, i, p, r0sq, 0.0);
    const EdgeTerm e2 = detail::edge_term<kGradient, true>(v2, i, p, r0sq, 0.0);
    outside |= int64_t(t < lanes) & int64_t(weight != 0.0) & (int64_t(e0.corner_dist2 >= r2) |
                                     int64_t(e1.corner_dist2 >= r2) |
                                     int64_t(e2.corner_dist2 >= r2));
    // The weight: a repeated triangle's multiplicity (a zero-area lane has all-zero edge
    // data, so its terms are exactly 0 whatever its weight).
    const double w = t < lanes ? weight : 0.0;
    sum += w * (e0.inside + e1.inside + e2.inside);
    if constexpr (kGradient) {
      const double dn = -2.0 * h * (e0.inside_dr0 + e1.inside_dr0 + e2.inside_dr0);
      sgx += w * (e0.gx + e1.gx + e2.gx + dn * nx);
      sgy += w * (e0.gy + e1.gy + e2.gy + dn * ny);
      sgz += w * (e0.gz + e1.gz + e2.gz + dn * nz);
    }
  }
  if (outside) return false;
  acc.value += inv_norm * sum;
  acc.gradient += inv_norm * Vec3(sgx, sgy, sgz);
  return true;
}

template <bool kGradient, class Index>
void TriangleBatch::evaluate(const Vec3& p, double radius, size_t count, Index index,
                             Accumulator& acc, bool try_wholly_inside) const {
  const double r2 = radius * radius;
  const double inv_norm = 1.0 / (6.0 * r2 * r2);
  EdgeView views[3];
  for (int k = 0; k < 3; ++k) {
    const EdgeArrays& e = edges_[k];
    views[k] = {e.vx.data(), e.vy.data(), e.vz.data(), e.ux.data(), e.uy.data(),
                e.uz.data(), e.mx.data(), e.my.data(), e.mz.data(), e.length.data()};
  }
  ChunkState st;
  st.pie_scale = 1.0 / (r2 * r2);
  ListedChunk chunk;
  bool try_lean = try_wholly_inside;
  for (size_t base = 0; base < count; base += kChunk) {
    const size_t lanes = std::min(kChunk, count - base);
    const auto lanes_of = chunk_lanes(index, base, lanes, chunk);
    const size_t from = chunk_base(index, base);
    // The lean path while chunks keep being wholly inside the support sphere (large radii);
    // after one that is not, the general path, until a chunk without pie slices suggests
    // trying again.
    if (try_lean && !acc.per_triangle && corners_within(p, r2, from, lanes, lanes_of, views) &&
        accumulate_wholly_inside<kGradient>(p, r2, inv_norm, from, lanes, lanes_of, views,
                                            acc)) {
      continue;
    }
    const bool any_pie =
        phase_one<kGradient>(p, r2, inv_norm, from, lanes, lanes_of, views, st);
    try_lean = try_wholly_inside && !any_pie;
    phase_two<kGradient>(st, base, lanes, any_pie, acc);
  }
}

// Phase 2: the pie angles (the only transcendental work, skipped when nothing is clipped),
// then each lane's value and gradient.
template <bool kGradient>
void TriangleBatch::phase_two(const ChunkState& st, size_t base, size_t lanes, bool any_pie,
                              Accumulator& acc) const {
  // A separate loop, so the call is unconditional and libmvec's SIMD atan2 serves it. One
  // call a lane for three edges (three_pie_angles), where the lanes that count touch the disk
  // and their angles sum to the arc inside the triangle: two calls (two_pie_angles and one
  // more) were 7 % of the soup's render. A lane whose turn is in doubt is summed the two-call
  // way after (with libm's atan2): the arc within 10^-9 of none or all of the circle.
  double theta[kChunk];
  if (any_pie) {
    const double scale = st.pie_scale;
    const auto simd_atan2 = [](double y, double x) { return atan2(y, x); };
    double doubt[kChunk];
    int64_t any_doubt = 0;
#pragma omp simd reduction(| : any_doubt)
    for (size_t t = 0; t < whole_simd_widths(lanes); ++t) {
      theta[t] = three_pie_angles(st.pie_y[0][t], st.pie_x[0][t], st.pie_y[1][t],
                                  st.pie_x[1][t], st.pie_y[2][t], st.pie_x[2][t], scale,
                                  simd_atan2, doubt[t]);
      // Only the lanes that count and touch the disk use the angle (the others take `whole`
      // below, or count nothing).
      doubt[t] = st.touches[t] && st.scale[t] != 0.0 ? doubt[t] : 0.0;
      any_doubt |= int64_t(doubt[t] != 0.0);
    }
    if (any_doubt) {
      const auto libm_atan2 = [](double y, double x) { return std::atan2(y, x); };
      for (size_t t = 0; t < lanes; ++t) {
        if (doubt[t] == 0.0) continue;
        theta[t] = two_pie_angles(st.pie_y[0][t], st.pie_x[0][t], st.pie_y[1][t],
                                  st.pie_x[1][t], scale, libm_atan2) +
                   std::atan2(st.pie_y[2][t], st.pie_x[2][t]);
      }
    }
  } else {
    std::fill(theta, theta + whole_simd_widths(lanes), 0.0);
  }
  double sum = 0.0, sgx = 0.0, sgy = 0.0, sgz = 0.0;
  // Each lane's value lands in `scaled` and is copied out after, if asked: a store under a
  // condition in the loop kept it scalar.
  double scaled[kChunk];
#pragma omp simd reduction(+ : sum, sgx, sgy, sgz)
  for (size_t t = 0; t < whole_simd_widths(lanes); ++t) {  // the repeated lanes' scale is 0
    // Every load unconditional (loads inside the selects became masked loads, vmaskmovpd).
    const double r0sq = st.r0sq[t], inside = st.inside[t], angle = theta[t];
    const double r4 = r0sq * r0sq;
    // No edge reaches the disk: it is wholly inside the triangle or wholly outside.
    const double whole = st.o_inside[t] ? 2.0 * kPi : 0.0;
    const double value = st.touches[t] ? inside + r4 * r0sq * angle : r4 * r0sq * whole;
    scaled[t] = st.scale[t] * value;
    sum += scaled[t];
    if constexpr (kGradient) {
      const double inplane = st.touches[t] ? 1.0 : 0.0;
      // A product, not a select: GCC sank the load into a select and masked it again (the
      // terms are finite: times 1 or 0 and plus 0, the same bits).
      const double dr0 = inplane * (st.inside_dr0[t] + 3.0 * r4 * angle) +
                         (1.0 - inplane) * (3.0 * r4 * whole);
      const double dn = -2.0 * st.h[t] * dr0;  // r0^2 = R^2 - h^2 moves with P as -2h n
      sgx += st.scale[t] * (inplane * st.gx[t] + dn * st.nx[t]);
      sgy += st.scale[t] * (inplane * st.gy[t] + dn * st.ny[t]);
      sgz += st.scale[t] * (inplane * st.gz[t] + dn * st.nz[t]);
    }
  }
  if (acc.per_triangle) std::copy(scaled, scaled + lanes, acc.per_triangle + base);
  acc.value += sum;
  acc.gradient += Vec3(sgx, sgy, sgz);
}

double TriangleBatch::value(const Vec3& p, double radius) const {
  Accumulator acc;
  evaluate<false>(p, radius, size(), Contiguous{}, acc);
  return acc.value;
}

FieldSample TriangleBatch::field(const Vec3& p, double radius) const {
  Accumulator acc;
  evaluate<true>(p, radius, size(), Contiguous{}, acc);
  return {acc.value, acc.gradient};
}

double TriangleBatch::value(const Vec3& p, double radius, std::span<const uint32_t> subset,
                            bool try_wholly_inside) const {
  Accumulator acc;
  evaluate<false>(p, radius, subset.size(), subset.data(), acc, try_wholly_inside);
  return acc.value;
}

FieldSample TriangleBatch::field(const Vec3& p, double radius, std::span<const uint32_t> subset,
                                 bool try_wholly_inside) const {
  Accumulator acc;
  evaluate<true>(p, radius, subset.size(), subset.data(), acc, try_wholly_inside);
  return {acc.value, acc.gradient};
}

double TriangleBatch::value_of_range(const Vec3& p, double radius, size_t first, size_t count,
                                     const double* mask, bool try_wholly_inside) const {
  Accumulator acc;
  evaluate<false>(p, radius, count, Masked{mask, first}, acc, try_wholly_inside);
  return acc.value;
}

void TriangleBatch::values(const Vec3& p, double radius, std::span<double> out) const {
  Accumulator acc;
  acc.per_triangle = out.data();
  evaluate<false>(p, radius, std::min(size(), out.size()), Contiguous{}, acc);
}

void TriangleBatch::values(std::span<const Vec3> points, double radius,
                           std::span<double> out) const {
  for (size_t k = 0; k < points.size() && k < out.size(); ++k) out[k] = value(points[k], radius);
}

}  // namespace convray::field
