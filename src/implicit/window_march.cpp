#include "implicit/window_march.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "core/bracket_refine.hpp"
#include "field/triangle_batch.hpp"
#include "field/triangle_quartic.hpp"
#include "implicit/line_curvature.hpp"

namespace convray::implicit {
namespace {

using Impl = ConvolutionSurface::Impl;

// Windows are not halved below this fraction of the smallest radius (the field only touches T).
constexpr double kResolution = 1e-3;
// The march steps at least this fraction of the smallest radius; such a step is not certified
// by the one-sided envelope and gets the two-sided test.
constexpr double kMinStep = 1.0 / 8.0;
// ... and at most this many smallest radii, the window over which the curvature is summed.
constexpr double kMaxStep = 2.0;

// F / T - 1 and its slope at t: in units of T, so that strengths from 1e-250 to 1e250 (and T
// with them) give the same steps and the envelopes' products neither overflow nor underflow.
struct Sample {
  double t, g, d;
};

// What an evaluation of the cluster's field returns: the value, its slope along the ray, and
// (only when asked) the full gradient.
enum class Want { value, slope, gradient };

// The cluster's primitives made ready to be summed at any t: the triangles of each mesh in
// one SIMD batch, evaluated for the lanes whose support holds the point; the rest one by one.
// A triangle that lies wholly inside the kernel's ball at p(t) (all three corners within R)
// adds its exact quartic in t instead (field/triangle_quartic.hpp): at large R most of them.
class ClusterField {
 public:
  // `origin_t`: where the march starts, the quartics' s = 0 (kept near the samples, so that
  // their powers of s do not cancel).
  ClusterField(const Impl& s, const Ray& ray, std::span<const accel::SupportInterval> cluster,
               double origin_t, TraceStats& stats);

  Sample sample(double t);  // value and slope, in units of T
  double value_minus_threshold(double t);  // F / T - 1
  Vec3 gradient(double t);
  // The sum of how far the primitives whose support meets [a, b] may bend up there (or down:
  // `upward` false), in units of T.
  double curvature(double a, double b, bool upward) const;
  double reach() const { return reach_; }

 private:
  struct Member {
    double enter, exit;
    uint32_t id;
  };
  struct Bending {  // a member's curvature along this ray
    double enter, exit;
    LineCurvature curvature;
  };
  struct Batch {
    const Impl::Group* group = nullptr;
    std::vector<field::Triangle> triangles;
    std::vector<double> enter, exit;                // the support along the ray
    std::vector<double> inside_enter, inside_exit;  // the whole triangle inside the ball
    std::vector<field::LineQuartic> quartics;       // in s = t - origin_t_
    field::TriangleBatch batch;
    std::vector<uint32_t> lanes;
  };
  template <Want kWant>
  field::FieldSample evaluate(double t, double* slope);
  Batch& batch_for(const Impl::Group& group);
  void add_triangle(Batch& b, const field::Triangle& triangle, double enter, double exit);

  const Impl& s_;
  const Ray& ray_;
  TraceStats& stats_;
  size_t batches_used_ = 0;
  double reach_ = -kInfinity;
  double origin_t_ = 0.0;  // where the quartics' parameter s is 0
  // Storage kept from ray to ray (a cluster is marched by one thread at a time).
  static thread_local std::vector<Bending> members_;  // every primitive, for the curvature
  static thread_local std::vector<Member> others_;    // those outside the batches
  static thread_local std::vector<Batch> batches_;
};

thread_local std::vector<ClusterField::Bending> ClusterField::members_;
thread_local std::vector<ClusterField::Member> ClusterField::others_;
thread_local std::vector<ClusterField::Batch> ClusterField::batches_;

ClusterField::ClusterField(const Impl& s, const Ray& ray,
                           std::span<const accel::SupportInterval> cluster, double origin_t,
                           TraceStats& stats)
    : s_(s), ray_(ray), stats_(stats), origin_t_(origin_t) {
  members_.clear();
  others_.clear();
  for (const accel::SupportInterval& iv : cluster) {
    reach_ = std::max(reach_, iv.exit);
    if (iv.primitive < s.triangle_base) {
      members_.push_back({iv.enter, iv.exit, LineCurvature(s, iv.primitive, ray)});
      others_.push_back({iv.enter, iv.exit, iv.primitive});
      continue;
    }
    const uint32_t triangle = iv.primitive - s.triangle_base;
    const Impl::Group& group = s.group_of(triangle);
    const field::Triangle& corners = s.triangles[triangle];
    members_.push_back(
        {iv.enter, iv.exit, LineCurvature(corners, group.strength, group.radius, ray)});
    add_triangle(batch_for(group), corners, iv.enter, iv.exit);
  }
  for (size_t k = 0; k < batches_used_; ++k) batches_[k].batch.assign(batches_[k].triangles);
}

ClusterField::Batch& ClusterField::batch_for(const Impl::Group& group) {
  for (size_t k = 0; k < batches_used_; ++k) {
    if (batches_[k].group == &group) return batches_[k];
  }
  if (batches_.size() == batches_used_) batches_.emplace_back();
  Batch& b = batches_[batches_used_++];
  b.group = &group;
  b.triangles.clear();
  b.enter.clear();
  b.exit.clear();
  b.inside_enter.clear();
  b.inside_exit.clear();
  b.quartics.clear();
  return b;
}

void ClusterField::add_triangle(Batch& b, const field::Triangle& triangle, double enter,
                                double exit) {
  b.triangles.push_back(triangle);
  b.enter.push_back(enter);
  b.exit.push_back(exit);
  // Where all three corners are within R of p(t): the intersection of their balls' chords.
  const double radius = b.group->radius;
  double lo = -kInfinity, hi = kInfinity;
  for (const Vec3& corner : {triangle.a, triangle.b, triangle.c}) {
    const Vec3 w = corner - ray_.origin;
    const double along = glm::dot(w, ray_.direction);
    const double across2 = glm::dot(w, w) - along * along;
    const double half2 = radius * radius - across2;
    if (!(half2 > 0.0)) {
      lo = kInfinity;
      break;
    }
    const double half = std::sqrt(half2);
    lo = std::max(lo, along - half);
    hi = std::min(hi, along + half);
  }
  // Shrunk by a hair, so rounding never takes a corner just outside for inside.
  const double margin = 1e-9 * radius;
  lo += margin;
  hi -= margin;
  b.inside_enter.push_back(lo);
  b.inside_exit.push_back(hi);
  b.quartics.push_back(lo < hi ? field::triangle_line_quartic(triangle, ray_.at(origin_t_),
                                                               ray_.direction, radius)
                               : field::LineQuartic{});
}

template <Want kWant>
field::FieldSample ClusterField::evaluate(double t, double* slope) {
  const Vec3 p = ray_.at(t);
  field::FieldSample sum;
  double along = 0.0;  // slope of the quartic parts
  const double s = t - origin_t_;
  for (size_t k = 0; k < batches_used_; ++k) {
    Batch& b = batches_[k];
    b.lanes.clear();
    field::LineQuartic inside;
    for (uint32_t lane = 0; lane < b.enter.size(); ++lane) {
      if (!(b.enter[lane] <= t && t <= b.exit[lane])) continue;
      if (kWant != Want::gradient && b.inside_enter[lane] <= t && t <= b.inside_exit[lane]) {
        inside.add(b.quartics[lane], 1.0);
      } else {
        b.lanes.push_back(lane);
      }
    }
    const double radius = b.group->radius, strength = b.group->strength;
    sum.value += strength * inside.value(s);
    if (kWant == Want::slope) along += strength * inside.slope(s);
    if (b.lanes.empty()) continue;
    stats_.field_evaluations += b.lanes.size();
    if constexpr (kWant == Want::value) {
      sum.value += strength * b.batch.value(p, radius, b.lanes);
    } else {
      sum += b.batch.field(p, radius, b.lanes) * strength;
    }
  }
  for (const Member& m : others_) {
    if (!(m.enter <= t && t <= m.exit)) continue;
    ++stats_.field_evaluations;
    if constexpr (kWant == Want::value) {
      sum.value += s_.value(m.id, p);
    } else {
      sum += s_.sample(m.id, p);
    }
  }
  if (slope) *slope = along + glm::dot(sum.gradient, ray_.direction);
  return sum;
}

Sample ClusterField::sample(double t) {
  double slope = 0.0;
  const field::FieldSample f = evaluate<Want::slope>(t, &slope);
  return {t, f.value / s_.threshold - 1.0, slope / s_.threshold};
}

double ClusterField::value_minus_threshold(double t) {
  return evaluate<Want::value>(t, nullptr).value / s_.threshold - 1.0;
}

Vec3 ClusterField::gradient(double t) { return evaluate<Want::gradient>(t, nullptr).gradient; }

double ClusterField::curvature(double a, double b, bool upward) const {
  double sum = 0.0;
  for (const Bending& m : members_) {
    if (m.enter > b) break;  // the cluster is sorted by entry
    if (m.exit < a) continue;
    sum += upward ? m.curvature.up(a, b) : m.curvature.down(a, b);
  }
  return sum / s_.threshold;
}

// How far from `a` the one-sided envelope keeps F on its side of T (infinite when nothing
// curves and the slope leads away from T).
double certified_step(const Sample& a, double curvature) {
  const double gap = std::abs(a.g);
  const double towards = a.g < 0.0 ? a.d : -a.d;  // slope towards T
  const double denominator = towards + std::sqrt(towards * towards + 2.0 * curvature * gap);
  return denominator > 0.0 ? 2.0 * gap / denominator : kInfinity;
}

// The root in (a.t, b.t) of the cubic Hermite interpolant of two samples on either side of T
// (their values and slopes), within O(h^4) of the field's root, and the interpolant's slope
// there: the refiner's first guess and first Newton step.
struct Guess {
  double t, slope;
};
Guess hermite_root(const Sample& a, const Sample& b) {
  const double h = b.t - a.t;
  const auto p = [&](double u) {
    const double u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * a.g + (u3 - 2 * u2 + u) * h * a.d + (3 * u2 - 2 * u3) * b.g +
           (u3 - u2) * h * b.d;
  };
  double lo = 0.0, hi = 1.0;
  const bool lo_negative = a.g < 0.0;
  for (int i = 0; i < 30; ++i) {  // bisection of the cubic to 1e-9 of the window: no field work
    const double mid = 0.5 * (lo + hi);
    ((p(mid) < 0.0) == lo_negative ? lo : hi) = mid;
  }
  const double u = 0.5 * (lo + hi);
  const double dp = (6 * u * u - 6 * u) * (a.g - b.g) + (3 * u * u - 4 * u + 1) * h * a.d +
                    (3 * u * u - 2 * u) * h * b.d;  // dp/du
  return {a.t + u * h, dp / h};
}

// Whether the Taylor envelopes of a and b (same side of T) keep F off T on [a.t, b.t].
bool window_excluded(const Sample& a, const Sample& b, double curvature) {
  const double h = b.t - a.t;
  // Below T the upper envelopes count (+M), above it the lower ones (-M); in both cases the
  // difference of the two envelopes is linear in s, so they meet at one point at most, and
  // the envelope nearest to T is largest there or at an end (where it is F itself).
  const double m = a.g < 0.0 ? curvature : -curvature;
  const double constant = a.g - b.g + b.d * h - 0.5 * m * h * h;
  const double slope = a.d - b.d + m * h;
  if (slope == 0.0) return true;
  const double s = -constant / slope;
  if (!(s > 0.0 && s < h)) return true;
  const double envelope = a.g + a.d * s + 0.5 * m * s * s;
  return a.g < 0.0 ? envelope < 0.0 : envelope > 0.0;
}

class Marcher {
 public:
  Marcher(const Impl& s, ClusterField& field, RootMode mode, std::vector<double>& out,
          TraceStats& stats)
      : s_(s), field_(field), mode_(mode), out_(out), stats_(stats) {}

  // Whether the search is over (a root found where one is enough). `at_cluster_entry`: `from`
  // is where the ray enters the cluster's first support.
  bool march(double from, double to, bool at_cluster_entry);
  double last_root() const { return last_root_; }

 private:
  bool bracket(const Sample& a, const Sample& b);
  bool search_window(const Sample& a, const Sample& b);
  double certified_reach(const Sample& a, double to, double min_step, double max_step) const;

  const Impl& s_;
  ClusterField& field_;
  RootMode mode_;
  std::vector<double>& out_;
  TraceStats& stats_;
  double last_root_ = kInfinity;
};

// A sign change between a and b: its root, refined on the exact field (for RootMode::any a
// point of the bracket is enough).
bool Marcher::bracket(const Sample& a, const Sample& b) {
  double t = b.t;
  if (mode_ != RootMode::any) {
    ++stats_.roots;
    const Guess guess = hermite_root(a, b);
    t = refine_bracket(a.t, b.t, a.g, b.g,
                             [&](double x) { return field_.value_minus_threshold(x); },
                             guess.t, guess.slope);
  }
  if (out_.empty() || t > out_.back() + 1e-9 * s_.min_radius) out_.push_back(t);
  last_root_ = t;
  return mode_ != RootMode::all;
}

// a and b on the same side of T: halve until the envelopes exclude a crossing pair, or the
// window is narrower than the resolution.
bool Marcher::search_window(const Sample& a, const Sample& b) {
  // Below T only how far F may bend up towards it counts; above it, how far down.
  if (window_excluded(a, b, field_.curvature(a.t, b.t, a.g < 0.0))) return false;
  if (b.t - a.t < kResolution * s_.min_radius) return false;
  ++stats_.subdivisions;
  const Sample mid = field_.sample(0.5 * (a.t + b.t));
  if ((mid.g < 0.0) != (a.g < 0.0)) {
    if (bracket(a, mid)) return true;
    return bracket(mid, b);
  }
  if (search_window(a, mid)) return true;
  return search_window(mid, b);
}

// How far from a the one-sided envelope certifies that F stays on a's side of T, up to
// max_step. The curvature bound sums the primitives whose support meets the window, so a
// short window has a smaller bound than a long one: windows double from min_step while the
// whole window is certified, and the step is the last certified length (a bound over a
// window holds over any part of it).
double Marcher::certified_reach(const Sample& a, double to, double min_step,
                                double max_step) const {
  double best = 0.0;
  for (double window = min_step;; window = std::min(2.0 * window, max_step)) {
    const double end = std::min(to, a.t + window);
    const double step = certified_step(a, field_.curvature(a.t, end, a.g < 0.0));
    if (step < window) return std::max(best, step);
    best = window;
    if (window >= max_step || a.t + window >= to) return best;
  }
}

bool Marcher::march(double from, double to, bool at_cluster_entry) {
  const double min_step = kMinStep * s_.min_radius, max_step = kMaxStep * s_.min_radius;
  // Where the ray enters the cluster's first support, every field of the cluster is zero with
  // a zero slope (each kernel vanishes with zero slope at its support's edge, and no other
  // support has begun): F = 0 < T, F' = 0, known without an evaluation.
  Sample a = at_cluster_entry ? Sample{from, -1.0, 0.0} : field_.sample(from);
  if (a.g == 0.0 && bracket(a, a)) return true;
  while (a.t < to) {
    ++stats_.fits;
    const double certified_length = certified_reach(a, to, min_step, max_step);
    const bool certified = certified_length >= min_step;
    const double step = std::clamp(certified_length, min_step, max_step);
    const Sample b = field_.sample(std::min(to, a.t + step));
    if ((a.g < 0.0) != (b.g < 0.0)) {
      if (bracket(a, b)) return true;
    } else if (!certified && search_window(a, b)) {
      return true;
    }
    a = b;
  }
  return false;
}

}  // namespace

void march_cluster(const Impl& surface, const Ray& ray,
                   std::span<const accel::SupportInterval> cluster, double tmin, double tmax,
                   RootMode mode, std::vector<double>& out, TraceStats& stats,
                   std::optional<Vec3>* first_gradient) {
  const double from = std::max(tmin, cluster.front().enter);
  ClusterField field(surface, ray, cluster, from, stats);
  const double to = std::min(tmax, field.reach());
  if (!(from < to)) return;
  Marcher marcher(surface, field, mode, out, stats);
  if (marcher.march(from, to, from == cluster.front().enter) && mode == RootMode::first &&
      first_gradient) {
    *first_gradient = field.gradient(marcher.last_root());
  }
}

}  // namespace convray::implicit
