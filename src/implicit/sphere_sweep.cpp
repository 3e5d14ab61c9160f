#include "implicit/sphere_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/polynomial_roots.hpp"
#include "implicit/entry_order.hpp"
#include "implicit/quartic.hpp"
#include "implicit/surface_impl.hpp"
#include "util/insertion_sort.hpp"

namespace convray::implicit {
namespace {

// A sphere whose chord holds the sweep's cursor: its field along the ray is
// k (h2 - (t - tc)^2)^2 until `exit`, with k = strength / r^4.
struct ActiveSphere {
  double exit = 0.0;
  double tc = 0.0, h2 = 0.0, k = 0.0;
  uint32_t id = 0;
};

// The running sum is rebuilt around the cursor when it has moved this many chord half-lengths
// from the sum's origin, so the power coefficients never cancel by more than a few digits.
constexpr double kRebaseReach = 4.0;
// The running sum's rounding: at most (updates + a few) ulps of the sum of the magnitudes of
// what was added; this factor covers 10^5 updates (a rebuild comes sooner).
constexpr double kRoundingFactor = 1e-10;
constexpr int kMaxUpdates = 4096;
// The same for a plain running sum of kMaxUpdates non-negative terms: (n eps) of their sum.
constexpr double kPeakRounding = 1e-12;

// Up to this many supports, sorting them by insertion beats std::sort (measured at 31).
constexpr size_t kInsertionSortLimit = 64;

// Per-thread storage, so that a ray allocates nothing once the vectors have grown.
struct SweepBuffers {
  std::vector<ActiveSphere> active;  // spheres whose chord holds the cursor
};

class SphereSweep {
 public:
  SphereSweep(const ConvolutionSurface::Impl& s, const SphereSweepRequest& request,
              std::vector<double>& out, TraceStats& stats, SweepBuffers& buffers)
      : s_(s), request_(request), out_(out), stats_(stats), active_(buffers.active) {}

  void run(std::span<accel::SupportInterval> supports, double tmin, double tmax);

 private:
  void enter(const accel::SupportInterval& support);
  void leave(double cursor);
  void add(const ActiveSphere& a, double sign);
  void rebase(double origin);
  bool may_cross(double lo, double hi) const;
  bool solve(double lo, double hi);
  Vec3 gradient(double t) const;

  const ConvolutionSurface::Impl& s_;
  const SphereSweepRequest& request_;
  std::vector<double>& out_;
  TraceStats& stats_;
  std::vector<ActiveSphere>& active_;

  Quartic sum_;        // the active spheres' field, in u = t - origin_
  Quartic magnitude_;  // sum of |coefficients| added or removed since the rebase
  double origin_ = 0.0, reach_ = 0.0;
  double first_exit_ = 0.0;  // the earliest exit among the active spheres
  // The sum of the active spheres' largest positive values bounds F from above (negative
  // strengths only lower it), and its magnitude bounds its rounding.
  double peaks_ = 0.0, peaks_magnitude_ = 0.0;
  int updates_ = 0;
};

void SphereSweep::add(const ActiveSphere& a, double sign) {
  const Quartic term = sphere_term(sign * a.k, a.h2, a.tc - origin_);
  sum_ += term;
  for (int k = 0; k < 5; ++k) magnitude_.c[k] += std::abs(term.c[k]);
  const double peak = std::max(a.k, 0.0) * a.h2 * a.h2;  // the sphere's largest value
  peaks_ += sign * peak;
  peaks_magnitude_ += peak;
  ++updates_;
}

// The chord's middle and half length give the closest approach and the squared half chord
// (accel::sphere_span computed the chord from them, so they agree to rounding).
void SphereSweep::enter(const accel::SupportInterval& support) {
  const double half = 0.5 * (support.exit - support.enter);
  if (!(half > 0.0)) return;  // a tangent ray: the field is zero along it
  if (active_.empty()) rebase(support.enter);
  const ActiveSphere a{support.exit, 0.5 * (support.enter + support.exit), half * half,
                       s_.sphere_weights[support.primitive], support.primitive};
  active_.push_back(a);
  first_exit_ = std::min(first_exit_, a.exit);
  add(a, 1.0);
  reach_ = std::max(reach_, kRebaseReach * half);
  ++stats_.fits;
}

// Drops the spheres whose chord ends at or before the cursor.
void SphereSweep::leave(double cursor) {
  first_exit_ = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < active_.size();) {
    const ActiveSphere a = active_[i];
    if (a.exit <= cursor) {
      active_[i] = active_.back();
      active_.pop_back();
      add(a, -1.0);
      continue;
    }
    first_exit_ = std::min(first_exit_, a.exit);
    ++i;
  }
  if (active_.empty()) rebase(cursor);  // nothing left: the sum is exactly zero
}

// Sums the active spheres' terms afresh around `origin` (exactly zero when none is active).
void SphereSweep::rebase(double origin) {
  origin_ = origin;
  sum_ = magnitude_ = Quartic{};
  peaks_ = peaks_magnitude_ = 0.0;
  for (const ActiveSphere& a : active_) add(a, 1.0);
  updates_ = 0;
}

// Whether F - T may vanish on [lo, hi]: the running sum's Bernstein hull over the piece, widened
// by a bound on the rounding of its coefficients (and of the shift and the conversion).
bool SphereSweep::may_cross(double lo, double hi) const {
  if (peaks_ + kPeakRounding * peaks_magnitude_ < s_.threshold) return false;  // F < T
  const double d = lo - origin_, width = hi - lo;
  const auto b = bernstein(shifted(sum_, d), width);
  const auto [least, most] = std::minmax_element(b.begin(), b.end());
  const double margin = kRoundingFactor * magnitude_(std::abs(d) + width);
  return *least - margin <= s_.threshold && *most + margin >= s_.threshold;
}

// The quartic summed afresh around lo from the active spheres' terms: every root in [lo, hi].
bool SphereSweep::solve(double lo, double hi) {
  Quartic q;
  for (const ActiveSphere& a : active_) q += sphere_term(a.k, a.h2, a.tc - lo);
  stats_.field_evaluations += active_.size();
  q.c[0] -= s_.threshold;
  const bool first_only = request_.mode != RootMode::all;
  // Below this width (in v) a piece is not halved any more: a pair of roots closer than this
  // (the quartic barely touching T) is told from a miss by the sign at its middle.
  const double ulps_of_t = 4.0 * std::numeric_limits<double>::epsilon() *
                          std::max(std::abs(lo), std::abs(hi));
  const double resolution = std::max(ulps_of_t, 1e-9 * s_.min_radius);
  double roots[4];
  const int count =
      polynomial_roots(q.c, 0.0, hi - lo, roots, first_only ? 1 : 4, resolution);
  bool found = false;
  for (int i = 0; i < count; ++i) {
    const double t = lo + roots[i];
    if (!out_.empty() && t <= out_.back() + 1e-9 * s_.min_radius) continue;  // a shared end
    out_.push_back(t);
    ++stats_.roots;
    found = true;
  }
  if (found && first_only && request_.gradient) *request_.gradient = gradient(out_.back());
  return found && first_only;
}

// The exact gradient at t from the active spheres: those whose support holds ray.at(t).
Vec3 SphereSweep::gradient(double t) const {
  const Vec3 p = request_.ray.at(t);
  Vec3 sum(0.0);
  for (const ActiveSphere& a : active_) {
    sum += s_.sphere_strengths[a.id] *
           field::point_field(p, s_.sphere_centers[a.id], s_.sphere_radii[a.id]).gradient;
  }
  return sum;
}

// Visits the chord ends in order: entries sorted (Embree hands them over nearly in order),
// exits found among the few active spheres.
void SphereSweep::run(std::span<accel::SupportInterval> supports, double tmin, double tmax) {
  const auto earlier = [](const accel::SupportInterval& a, const accel::SupportInterval& b) {
    return a.enter < b.enter;
  };
  // Embree's order is nearly sorted, but its inversions grow as n^2 (about n^2 / 10).
  if (supports.size() <= kInsertionSortLimit) {
    insertion_sort(supports, earlier);
  } else {
    sort_by_entry(supports);
  }
  active_.clear();
  reach_ = 0.0;
  first_exit_ = std::numeric_limits<double>::infinity();
  size_t next = 0;
  const size_t n = supports.size();
  while (true) {
    double cursor = first_exit_;
    if (next < n) cursor = std::min(cursor, supports[next].enter);
    if (!(cursor < tmax)) return;  // also: nothing left (infinity)
    // Entries first: a chord of zero length at the cursor enters and leaves at once.
    while (next < n && supports[next].enter <= cursor) enter(supports[next++]);
    if (first_exit_ <= cursor) leave(cursor);
    if (active_.empty()) continue;
    double end = first_exit_;
    if (next < n) end = std::min(end, supports[next].enter);
    const double lo = std::max(cursor, tmin), hi = std::min(end, tmax);
    if (!(lo < hi)) continue;
    if (lo - origin_ > reach_ || updates_ > kMaxUpdates) rebase(lo);
    if (may_cross(lo, hi) && solve(lo, hi)) return;
  }
}

}  // namespace

bool only_spheres(const ConvolutionSurface::Impl& surface,
                  std::span<const accel::SupportInterval> cluster) {
  return std::all_of(cluster.begin(), cluster.end(), [&](const accel::SupportInterval& iv) {
    return iv.primitive < surface.capsule_base;
  });
}

void sweep_spheres(const ConvolutionSurface::Impl& surface, const SphereSweepRequest& request,
                   std::span<accel::SupportInterval> supports, double tmin, double tmax,
                   std::vector<double>& out, TraceStats& stats) {
  thread_local SweepBuffers buffers;
  SphereSweep sweep(surface, request, out, stats, buffers);
  sweep.run(supports, tmin, tmax);
}

}  // namespace convray::implicit
