#pragma once
// Triangles prepared for batched field evaluation: structure-of-arrays, one SIMD lane per
// triangle, edge frames precomputed. Same mathematics as triangle.hpp (the exact scalar twin
// that tests compare this with); evaluation is branch-free per lane, and the atan2 of the pie
// slices runs only for chunks where some triangle is clipped by the support sphere.
#include <cstdint>
#include <span>
#include <vector>

#include "field/sample.hpp"
#include "field/triangle.hpp"
#include "field/triangle_frame.hpp"
#include "util/simd_width.hpp"

namespace convray::field {

namespace detail {
struct EdgeView;
struct ChunkState;
}  // namespace detail

class TriangleBatch {
 public:
  TriangleBatch() = default;
  explicit TriangleBatch(std::span<const Triangle> triangles);
  // Each triangle's field times its weight (a repeated triangle's multiplicity).
  TriangleBatch(std::span<const Triangle> triangles, std::span<const double> weights);
  // Replaces the triangles, reusing the arrays' storage (for small batches built per query).
  void assign(std::span<const Triangle> triangles);

  size_t size() const { return size_; }

  // Lane by lane, for batches whose lanes are set only when first needed (the window march's,
  // many of whose triangles are never sampled clipped): n lanes of unspecified content, each
  // set by set_lane before a call lists it (the listed calls read only the listed lanes).
  // The arrays only ever grow here: shrinking and growing them again for every cluster
  // filled the new lanes with zeros each time (1.6 % of a render's instructions).
  void resize_unset(size_t n) {
    if (n + kSimdWidth > weight_.size()) resize(n);  // room for value_of_range's widths
    size_ = n;
  }
  // Lane i holds `triangle`, whose frame is `frame` (triangle_frame(triangle), computed once
  // per mesh): the same lane, bit for bit, as assign() makes, without a square root or
  // division per ray.
  void set_lane(size_t i, const Triangle& triangle, const TriangleFrame& frame);

  // Sum of the raw fields (strength 1) of all triangles, or of the listed ones.
  double value(const Vec3& p, double radius) const;
  FieldSample field(const Vec3& p, double radius) const;
  // `try_wholly_inside` false: the caller knows the listed triangles are mostly clipped by
  // the support sphere (the window march lists its wholly inside ones apart), so the cheap
  // path for wholly inside chunks is not tried first.
  double value(const Vec3& p, double radius, std::span<const uint32_t> subset,
               bool try_wholly_inside = true) const;
  FieldSample field(const Vec3& p, double radius, std::span<const uint32_t> subset,
                    bool try_wholly_inside = true) const;

  // The lanes [first, first + count) in place, lane i counted mask[i] (0 or 1) times: the
  // listed lanes' sum where they lie close together, without the gathers a list needs. Every
  // lane of the range holds a triangle (set_lane, or any earlier one: its terms are finite and
  // masked out); mask has room for whole SIMD widths from `first`.
  double value_of_range(const Vec3& p, double radius, size_t first, size_t count,
                        const double* mask, bool try_wholly_inside = true) const;

  // One value per triangle (out.size() == size()).
  void values(const Vec3& p, double radius, std::span<double> out) const;
  // The summed field at many points (out.size() == points.size()).
  void values(std::span<const Vec3> points, double radius, std::span<double> out) const;

 private:
  struct EdgeArrays {
    std::vector<double> vx, vy, vz;  // start vertex
    std::vector<double> ux, uy, uz;  // unit direction
    std::vector<double> mx, my, mz;  // in-plane unit normal, pointing into the triangle
    std::vector<double> length;
  };
  struct Accumulator;
  void resize(size_t n);
  template <bool kGradient, class Index>
  void evaluate(const Vec3& p, double radius, size_t count, Index index, Accumulator& acc,
                bool try_wholly_inside = true) const;
  // The chunk's loops, over whole SIMD widths (the lanes past `lanes` masked out).
  template <class Index>
  bool corners_within(const Vec3& p, double r2, size_t base, size_t lanes, Index index,
                      const detail::EdgeView* views) const;
  template <bool kGradient, class Index>
  bool accumulate_wholly_inside(const Vec3& p, double r2, double inv_norm, size_t base,
                                size_t lanes, Index index, const detail::EdgeView* views,
                                Accumulator& acc) const;
  template <bool kGradient>
  void phase_two(const detail::ChunkState& st, size_t base, size_t lanes, bool any_pie,
                 Accumulator& acc) const;
  template <bool kGradient, class Index>
  bool phase_one(const Vec3& p, double r2, double inv_norm, size_t base, size_t lanes,
                 Index index, const detail::EdgeView* views, detail::ChunkState& st) const;

  std::vector<double> nx_, ny_, nz_;  // unit normal (zero for zero-area triangles)
  std::vector<double> weight_;        // the triangle's weight (1 unless given), 0 for zero area
  size_t size_ = 0;  // the lanes in use (the arrays hold more: whole SIMD widths at least)
  EdgeArrays edges_[3];
};

}  // namespace convray::field
