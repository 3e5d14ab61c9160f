#pragma once
// The summed exact field of one cluster of supports along a ray, for the window march
// (window_march.cpp): its members made ready as the march reaches them, sampled by value or
// with the gradient, and the sums of their curvature bounds over a window.
#include <cstdint>
#include <span>
#include <vector>

#include "accel/support_index.hpp"
#include "accel/triangle_line.hpp"
#include "core/ray.hpp"
#include "core/trace_stats.hpp"
#include "field/triangle_batch.hpp"
#include "field/triangle_quartic.hpp"
#include "implicit/down_bend_table.hpp"
#include "implicit/line_curvature.hpp"
#include "implicit/surface_impl.hpp"

namespace convray::implicit {

// The cluster's primitives made ready to be summed at any t: the triangles of each mesh in
// one SIMD batch, evaluated for the lanes whose support holds the point; the rest one by one.
// A triangle that lies wholly inside the kernel's ball at p(t) (all three corners within R)
// adds its exact quartic in t instead (field/triangle_quartic.hpp): at large R most of them.
class ClusterField {
 public:
  // `origin_t`: where the march starts, the quartics' s = 0 (kept near the samples, so that
  // their powers of s do not cancel).
  ClusterField(const ConvolutionSurface::Impl& s, const Ray& ray,
               std::span<const accel::SupportInterval> cluster,
               const accel::TriangleLineTable& lines, double origin_t, TraceStats& stats);

  double value_minus_threshold(double t);  // F / T - 1
  field::FieldSample sample(double t);     // F and its gradient
  const Ray& ray() const { return ray_; }
  // The sum of how far the primitives whose support meets [a, b] may bend up there (or down:
  // `upward` false), in units of T. `anywhere`: each primitive's bound over its whole line
  // where it has a cheap one (LineCurvature::down_anywhere), larger but quick to sum.
  double curvature(double a, double b, bool upward, bool anywhere = false);
  double reach() const { return reach_; }
  // The sum of Impl::bend_bound over the primitives whose support holds p(t) (the members
  // entered by t are added first).
  double bend_bound_at(double t);

 private:
  // What an evaluation of the cluster's field returns: the value, or also the gradient (the
  // first hit's normal).
  enum class Want { value, gradient };
  struct Member {
    double enter, exit;
    uint32_t id;
  };
  struct Bending {  // a member's curvature along this ray
    double enter, exit;
    LineCurvature curvature;
  };
  struct Batch {
    const ConvolutionSurface::Impl::Group* group = nullptr;
    std::vector<uint32_t> triangles;                // indices into the surface's triangles
    std::vector<double> enter, exit;                // the support along the ray
    std::vector<double> inside_enter, inside_exit;  // the whole triangle inside the ball
    std::vector<field::LineQuartic> quartics;       // in s = t - origin_t_, made when
    std::vector<uint8_t> has_quartic;               // first summed (many never are)
    field::TriangleBatch batch;
    std::vector<uint8_t> lane_set;  // batch lanes are set when first listed
    // The lanes at the sample, listed by evaluate: those clipped by the support sphere, and
    // those wholly inside it. Room for every member of the cluster (sized with the batch).
    std::vector<uint32_t> clipped_room, inside_room;
    std::vector<double> listed;  // 1 for the clipped lanes, else 0 (value_of_range)
  };
  template <Want kWant>
  field::FieldSample evaluate(double t);
  // Members are made ready in the cluster's order as the march reaches their entry: a first
  // hit ends the march long before the last members of a deep cluster (at R = 5, half of
  // them), whose set-up (curvature terms, batch lanes, inside chords) is then never paid.
  void add_members_entered_by(double t);
  void add_member(const accel::SupportInterval& iv);
  Batch& batch_for(const ConvolutionSurface::Impl::Group& group);
  void add_triangle(Batch& b, uint32_t triangle, double enter, double exit,
                    const accel::Span& corners_within);
  // The clipped lanes' values (`lanes`, ascending, not empty), summed.
  static double clipped_value(Batch& b, std::span<const uint32_t> lanes, const Vec3& p,
                              double radius);
  // Sets the batch's lane (on its first sample) and the triangle's quartic (on its first
  // sample wholly inside), each made once per ray.
  void set_lane(Batch& b, uint32_t lane);
  const field::LineQuartic& quartic(Batch& b, uint32_t lane);

  void make_members() const;

  const ConvolutionSurface::Impl& s_;
  const Ray& ray_;
  TraceStats& stats_;
  std::span<const accel::SupportInterval> cluster_;
  const accel::TriangleLineTable& lines_;
  size_t members_added_ = 0;  // cluster_[0, members_added_) are in the batches and the table
  size_t batches_used_ = 0;
  double reach_ = -kInfinity;
  double origin_t_ = 0.0;  // where the quartics' parameter s is 0
  mutable bool members_ready_ = false;
  // Storage kept from ray to ray (a cluster is marched by one thread at a time).
  // Every primitive's curvature, made when first needed (make_members).
  static thread_local std::vector<Bending> members_;
  // Their downward bounds side by side (the march's usual question); unused (`by_table_`
  // false) when a member has a negative strength, whose down is its field's up.
  static thread_local DownBendTable down_;
  bool by_table_ = true;
  static thread_local std::vector<Member> others_;    // those outside the batches
  static thread_local std::vector<Batch> batches_;
};

}  // namespace convray::implicit
