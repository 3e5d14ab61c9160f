#include "implicit/window_march.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "core/bracket_refine.hpp"
#include "field/triangle_batch.hpp"
#include "field/triangle_quartic.hpp"
#include "implicit/down_bend_table.hpp"
#include "implicit/inside_balls.hpp"
#include "implicit/line_curvature.hpp"
#include "implicit/near_hit.hpp"

namespace convray::implicit {
namespace {

using Impl = ConvolutionSurface::Impl;

// Windows are not halved below this fraction of the smallest radius (the field only touches T).
constexpr double kResolution = 1e-3;
// Roots are bracketed to this fraction of the smallest radius: the tests ask for 10^-6 of R
// against the reference tracer, and a picture sees far less. (The last steps to a few ulps
// cost one or two exact evaluations of the cluster per root: 3 % of a render.)
constexpr double kRootTolerance = 1e-10;
// A first hit's refiner stops once its next point should lie within this fraction of the
// smallest radius of the root, and leaves that point to the evaluation with the gradient that
// the normal needs anyway: Newton's step from there (error about the square of the distance)
// closes the root to the tolerance. One value evaluation fewer per hit than landing within the
// tolerance itself (the dragon at R = 1: field evaluations 12.8M -> 11.4M); the normal is the
// exact gradient at that point, within about 1e-5 of a radian of the one at the root (the
// reference tests: 1.3e-5 at worst). Landing within 1e-5 R instead (9e-6 at worst) cost
// more value evaluations: the dragon's field evaluations 10.0M and 94.8M at R = 1 and 5,
// against 9.78M and 90.9M.
constexpr double kLanding = 1e-4;
// Windows are at least this fraction of the smallest radius (halved when their chord bound
// cannot exclude T) ...
constexpr double kMinStep = 1.0 / 8.0;
// ... and at most this many smallest radii.
constexpr double kMaxStep = 2.0;
// Each next window is the longest whose chord bound would exclude T if F ended it where it
// started (D h^2 / 8 below the gap to T). Asking for a margin (half the gap, a quarter) gave
// more, shorter windows: render instructions (callgrind) 1.05-1.18 times as many.
// A shadow ray found blocked leaves a ball inside the surface for the next rays of its run
// (inside_balls.hpp): the largest certified around this many points, this many smallest radii
// apart, from the first sample found inside (the field peaks about a radius in).
constexpr int kProbePoints = 4;
constexpr double kProbeStep = 0.25;
// A first hit's refiner starts from the root of the tangent plane at the last first hit of
// its run (the near-hit sample, near_hit.hpp) where the ray passes within this many smallest
// radii of that point. The soup's neighbouring camera rays pass 0.01-0.1 R apart: the plane's
// root lay mostly 1e-5 to 1e-3 R from the root, the parabola's through the window's samples
// 1e-3 to 1e-1 R, and field evaluations fell from 28.3M to 26.9M. Further off the plane's
// error (about the squared distance over the surface's radius of curvature) is the larger:
// on the dragon at R = 1, rays 0.1-1 R apart, 9.47M rose to 9.68M without this reach.
constexpr double kTangentReach = 0.05;

// What an evaluation of the cluster's field returns: the value, or also the gradient (the
// first hit's normal).
enum class Want { value, gradient };

// The cluster's primitives made ready to be summed at any t: the triangles of each mesh in
// one SIMD batch, evaluated for the lanes whose support holds the point; the rest one by one.
// A triangle that lies wholly inside the kernel's ball at p(t) (all three corners within R)
// adds its exact quartic in t instead (field/triangle_quartic.hpp): at large R most of them.
class ClusterField {
 public:
  // `origin_t`: where the march starts, the quartics' s = 0 (kept near the samples, so that
  // their powers of s do not cancel).
  // `search`: which of the thread's two sets of batches to use (see batch_sets_).
  ClusterField(const Impl& s, const Ray& ray, std::span<const accel::SupportInterval> cluster,
               const accel::TriangleLineTable& lines, double origin_t, RootMode search,
               TraceStats& stats);

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
  struct Member {
    double enter, exit;
    uint32_t id;
  };
  struct Bending {  // a member's curvature along this ray
    double enter, exit;
    LineCurvature curvature;
  };
  // Its arrays are sized for the cluster once (and only grow, kept from ray to ray), and
  // filled up to `size`: a push_back per array and member was a third of add_member.
  struct Batch {
    const Impl::Group* group = nullptr;
    size_t size = 0;                                // the lanes listed so far
    std::vector<uint32_t> triangles;                // indices into the surface's triangles
    std::vector<double> enter, exit;                // the support along the ray
    std::vector<double> inside_enter, inside_exit;  // the whole triangle inside the ball
    std::vector<field::LineQuartic> quartics;       // in s = t - origin_t_, made when
    std::vector<uint8_t> has_quartic;               // first summed (many never are)
    field::TriangleBatch batch;
    // Which triangle each batch lane holds (kNotLoaded: none), of which surface: the lanes
    // are set when first listed, and kept from ray to ray (see batch_sets_).
    std::vector<uint32_t> loaded;
    uint64_t loaded_serial = 0;
    // The lanes at the sample, listed by evaluate: those clipped by the support sphere, and
    // those wholly inside it. Room for every member of the cluster (sized with the batch).
    std::vector<uint32_t> clipped_room, inside_room;
    // make_quartics' room: the lanes without a quartic, their triangles and new quartics.
    std::vector<uint32_t> new_lanes, new_triangles;
    std::vector<field::LineQuartic> new_quartics;
    std::vector<double> listed;  // 1 for the clipped lanes, else 0 (value_of_range)
  };
  template <Want kWant>
  field::FieldSample evaluate(double t);
  // Members are made ready in the cluster's order as the march reaches their entry: a first
  // hit ends the march long before the last members of a deep cluster (at R = 5, half of
  // them), whose set-up (curvature terms, batch lanes, inside chords) is then never paid.
  void add_members_entered_by(double t);
  void add_member(const accel::SupportInterval& iv);
  Batch& batch_for(const Impl::Group& group);
  void add_triangle(Batch& b, uint32_t triangle, double enter, double exit,
                    const accel::Span& corners_within);
  // The clipped lanes' values (`lanes`, ascending, not empty), summed.
  static double clipped_value(Batch& b, std::span<const uint32_t> lanes, const Vec3& p,
                              double radius);
  // Sets the batch's lane (on its first sample, unless an earlier ray left the same triangle
  // there); makes the quartics of the `lanes` that have none yet (on their first sample wholly
  // inside, once per ray), together.
  void set_lane(Batch& b, uint32_t lane);
  void make_quartics(Batch& b, std::span<const uint32_t> lanes);

  void make_members() const;

  const Impl& s_;
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
  // Two sets, one for first-hit searches and one for the rest (shadow rays), as each kind
  // comes one after the other: neighbouring camera rays list mostly the same triangles in the
  // same lanes, whose set_lane is then skipped (the soup: 92 % of the lanes its samples need,
  // the dragon at R = 5 64 %), where one set would be overwritten by the shadow ray of the hit
  // in between.
  static thread_local std::vector<Batch> batch_sets_[2];
  std::vector<Batch>& batches_;
  static constexpr uint32_t kNotLoaded = std::numeric_limits<uint32_t>::max();
};

thread_local std::vector<ClusterField::Bending> ClusterField::members_;
thread_local DownBendTable ClusterField::down_;
thread_local std::vector<ClusterField::Member> ClusterField::others_;
thread_local std::vector<ClusterField::Batch> ClusterField::batch_sets_[2];

ClusterField::ClusterField(const Impl& s, const Ray& ray,
                           std::span<const accel::SupportInterval> cluster,
                           const accel::TriangleLineTable& lines, double origin_t,
                           RootMode search, TraceStats& stats)
    : s_(s), ray_(ray), stats_(stats), cluster_(cluster), lines_(lines), origin_t_(origin_t),
      batches_(batch_sets_[search == RootMode::first ? 0 : 1]) {
  others_.clear();
  down_.reset(cluster.size());
  for (const accel::SupportInterval& iv : cluster) reach_ = std::max(reach_, iv.exit);
}

void ClusterField::add_members_entered_by(double t) {
  while (members_added_ < cluster_.size() && cluster_[members_added_].enter <= t) {
    add_member(cluster_[members_added_++]);
  }
}

// A member with a negative strength keeps the table out from then on (its down is its
// field's up); the table's sums only ever involve members added before it.
void ClusterField::add_member(const accel::SupportInterval& iv) {
  if (iv.primitive < s_.triangle_base) {
    const LineCurvature curvature(s_, iv.primitive, ray_);
    by_table_ = by_table_ && !curvature.flipped();
    if (by_table_) down_.add(iv.enter, iv.exit, curvature.down_terms());
    others_.push_back({iv.enter, iv.exit, iv.primitive});
    return;
  }
  const uint32_t triangle = iv.primitive - s_.triangle_base;
  const Impl::Group& group = s_.group_of(triangle);
  by_table_ = by_table_ && !(group.strength < 0.0);
  if (by_table_) {
    down_.add(iv.enter, iv.exit,
              LineCurvature::triangle_down_terms(lines_.twice_area(iv.terms), group.strength,
                                                 group.radius, lines_.reach(iv.terms)));
  }
  add_triangle(batch_for(group), triangle, iv.enter, iv.exit,
               lines_.corners_within(iv.terms));
}

// Every member's whole LineCurvature, for the upward bounds (asked only above T, after a
// crossing) or where a negative strength keeps the table out.
void ClusterField::make_members() const {
  members_.clear();
  for (const accel::SupportInterval& iv : cluster_) {
    if (iv.primitive < s_.triangle_base) {
      members_.push_back({iv.enter, iv.exit, LineCurvature(s_, iv.primitive, ray_)});
      continue;
    }
    const uint32_t triangle = iv.primitive - s_.triangle_base;
    const Impl::Group& group = s_.group_of(triangle);
    members_.push_back({iv.enter, iv.exit,
                        LineCurvature(s_.triangles[triangle], s_.frames[triangle],
                                      group.strength, group.radius, ray_)});
  }
  members_ready_ = true;
}

ClusterField::Batch& ClusterField::batch_for(const Impl::Group& group) {
  for (size_t k = 0; k < batches_used_; ++k) {
    if (batches_[k].group == &group) return batches_[k];
  }
  if (batches_.size() == batches_used_) batches_.emplace_back();
  Batch& b = batches_[batches_used_++];
  if (b.group != &group || b.loaded_serial != s_.serial) {
    std::fill(b.loaded.begin(), b.loaded.end(), kNotLoaded);
    b.loaded_serial = s_.serial;
  }
  b.group = &group;
  b.size = 0;
  const size_t n = cluster_.size();
  if (b.triangles.size() < n) {
    for (auto* v : {&b.enter, &b.exit, &b.inside_enter, &b.inside_exit}) v->resize(n);
    b.triangles.resize(n);
    b.quartics.resize(n);
    b.has_quartic.resize(n);
  }
  // Lanes for as many members as the cluster has (most clusters meet one mesh): sized once.
  b.batch.resize_unset(cluster_.size());
  if (b.loaded.size() < cluster_.size()) b.loaded.resize(cluster_.size(), kNotLoaded);
  const size_t mask_size = cluster_.size() + kSimdWidth;  // value_of_range reads whole widths
  if (b.listed.size() < mask_size) b.listed.resize(mask_size);
  if (b.clipped_room.size() < cluster_.size()) {
    b.clipped_room.resize(cluster_.size());
    b.inside_room.resize(cluster_.size());
    b.new_lanes.resize(cluster_.size());
    b.new_triangles.resize(cluster_.size());
    b.new_quartics.resize(cluster_.size());
  }
  return b;
}

void ClusterField::add_triangle(Batch& b, uint32_t index, double enter, double exit,
                                const accel::Span& corners_within) {
  const size_t lane = b.size++;
  b.triangles[lane] = index;
  b.enter[lane] = enter;
  b.exit[lane] = exit;
  // Where all three corners are within R of p(t), shrunk by a hair, so rounding never takes a
  // corner just outside for inside.
  const double margin = 1e-9 * b.group->radius;
  b.inside_enter[lane] = corners_within.enter + margin;
  b.inside_exit[lane] = corners_within.exit - margin;
  b.has_quartic[lane] = 0;
}

// Where the listed lanes lie close together (at most twice the SIMD widths from the first to
// the last as they fill), their range is read in place with the others masked out: a gather
// per array and width (vgatherqpd) made half the time of a listed width. The soup: 12.6 lanes
// from the first listed to the last for 9.9 listed; the dragon at R = 5, whose quartic lanes
// lie between, 47 for 29. Renders, 5 pairs against the list: R = 1 0.94, the soup 0.93,
// R = 5 0.97. (At most one width more than the list instead: the same within 1 %.)
double ClusterField::clipped_value(Batch& b, std::span<const uint32_t> lanes, const Vec3& p,
                                   double radius) {
  const size_t first = lanes.front(), count = lanes.back() - first + 1;
  if (whole_simd_widths(count) > 2 * whole_simd_widths(lanes.size())) {
    return b.batch.value(p, radius, lanes, false);
  }
  std::fill(b.listed.begin() + first, b.listed.begin() + first + count, 0.0);
  for (uint32_t lane : lanes) b.listed[lane] = 1.0;
  return b.batch.value_of_range(p, radius, first, count, b.listed.data(), false);
}

void ClusterField::set_lane(Batch& b, uint32_t lane) {
  const uint32_t triangle = b.triangles[lane];
  if (b.loaded[lane] == triangle) return;
  b.batch.set_lane(lane, s_.triangles[triangle], s_.frames[triangle]);
  b.loaded[lane] = triangle;
}

void ClusterField::make_quartics(Batch& b, std::span<const uint32_t> lanes) {
  size_t count = 0;
  for (uint32_t lane : lanes) {
    b.new_lanes[count] = lane;
    b.new_triangles[count] = b.triangles[lane];
    count += !b.has_quartic[lane];
  }
  if (count == 0) return;
  const std::span<field::LineQuartic> made(b.new_quartics.data(), count);
  field::triangle_line_quartics(s_.triangles, s_.frames, {b.new_triangles.data(), count},
                                ray_.at(origin_t_), ray_.direction, b.group->radius, made);
  for (size_t k = 0; k < count; ++k) {
    b.quartics[b.new_lanes[k]] = made[k];
    b.has_quartic[b.new_lanes[k]] = 1;
  }
}

template <Want kWant>
field::FieldSample ClusterField::evaluate(double t) {
  add_members_entered_by(t);
  const Vec3 p = ray_.at(t);
  field::FieldSample sum;
  for (size_t k = 0; k < batches_used_; ++k) {
    Batch& b = batches_[k];
    // Every lane is written and the count moves on where it belongs: a branch per lane (in
    // its support? wholly inside?) mispredicted on most, the lanes of a ray coming and going
    // in no order the predictor learns.
    uint32_t* clipped = b.clipped_room.data();
    uint32_t* inside = b.inside_room.data();
    size_t clipped_count = 0, inside_count = 0;
    for (uint32_t lane = 0; lane < b.size; ++lane) {
      const bool in_support = (b.enter[lane] <= t) & (t <= b.exit[lane]);
      const bool wholly_inside = (b.inside_enter[lane] <= t) & (t <= b.inside_exit[lane]);
      clipped[clipped_count] = lane;
      inside[inside_count] = lane;
      clipped_count += in_support & !wholly_inside;
      inside_count += in_support & wholly_inside;
    }
    const std::span<const uint32_t> clipped_lanes(clipped, clipped_count);
    const std::span<const uint32_t> inside_lanes(inside, inside_count);
    for (uint32_t lane : clipped_lanes) set_lane(b, lane);
    const double radius = b.group->radius, strength = b.group->strength;
    stats_.field_evaluations += clipped_count + inside_count;
    if constexpr (kWant == Want::value) {
      // Wholly inside: the triangle's exact quartic in s, summed in the lanes' order.
      make_quartics(b, inside_lanes);
      field::LineQuartic quartics;
      for (uint32_t lane : inside_lanes) quartics.add(b.quartics[lane], 1.0);
      sum.value += strength * quartics.value(t - origin_t_);
      if (clipped_count > 0) sum.value += strength * clipped_value(b, clipped_lanes, p, radius);
    } else {
      // The batch's cheap path for wholly inside triangles is tried only on the lanes known to
      // be so: a chunk that mixes them with clipped ones takes the general path for all (the
      // dragon's gradient samples at R = 5 cost 1.5 times the instructions that way).
      for (uint32_t lane : inside_lanes) set_lane(b, lane);
      if (inside_count > 0) sum += b.batch.field(p, radius, inside_lanes) * strength;
      if (clipped_count > 0) sum += b.batch.field(p, radius, clipped_lanes, false) * strength;
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
  return sum;
}

double ClusterField::bend_bound_at(double t) {
  add_members_entered_by(t);
  double sum = 0.0;
  for (size_t k = 0; k < batches_used_; ++k) {
    const Batch& b = batches_[k];
    for (size_t lane = 0; lane < b.size; ++lane) {
      if (b.enter[lane] <= t && t <= b.exit[lane]) {
        sum += s_.bend_bound(s_.triangle_base + b.triangles[lane]);
      }
    }
  }
  for (const Member& m : others_) {
    if (m.enter <= t && t <= m.exit) sum += s_.bend_bound(m.id);
  }
  return sum;
}

double ClusterField::value_minus_threshold(double t) {
  return evaluate<Want::value>(t).value / s_.threshold - 1.0;
}

field::FieldSample ClusterField::sample(double t) { return evaluate<Want::gradient>(t); }

double ClusterField::curvature(double a, double b, bool upward, bool anywhere) {
  add_members_entered_by(b);
  if (!upward && by_table_) return down_.sum(a, b, anywhere) / s_.threshold;
  if (!members_ready_) make_members();
  double sum = 0.0;
  for (const Bending& m : members_) {
    if (m.enter > b) break;  // the cluster is sorted by entry
    if (m.exit < a) continue;
    if (anywhere && !upward) {
      sum += m.curvature.down_anywhere();
    } else {
      sum += upward ? m.curvature.up(a, b) : m.curvature.down(a, b);
    }
  }
  return sum / s_.threshold;
}

// The refiner's first guess for a root and the slope of the curve that gave it.
struct Guess {
  double t, slope;
};

// F / T - 1 at t: in units of T, so that strengths from 1e-250 to 1e250 (and T with them)
// give the same windows and the bounds' products neither overflow nor underflow. No slope:
// a value costs about half a sample with the gradient (field_bench).
struct Value {
  double t, g;
};

// The largest amount by which F may rise above the chord between a and b (below T), or sink
// below it (above T), given a bound M on how far it bends the other way: F'' >= -M gives
// F <= chord + M s (h - s) / 2 on the window, a concave quadratic whose peak is found exactly.
// Whether that bound keeps F off T on [a.t, b.t] (a and b on the same side of T).
bool chord_excluded(const Value& a, const Value& b, double bend) {
  const double h = b.t - a.t;
  const double sign = a.g < 0.0 ? 1.0 : -1.0;  // below T: how far F rises; above: sinks
  const double ga = sign * a.g, gb = sign * b.g;  // both negative
  if (!(bend >= 0.0)) return false;  // no bound (NaN): nothing can be excluded
  if (bend == 0.0) return true;       // F is linear: the chord itself
  const double s = std::clamp(0.5 * h + (gb - ga) / (bend * h), 0.0, h);
  return ga + (gb - ga) * s / h + 0.5 * bend * s * (h - s) < 0.0;
}

// The root in (a.t, b.t) of the parabola through three values (a and b on either side of
// T, c a third point near them) and its slope there: the refiner's first guess and Newton
// step, within O(h^3) of the field's root. NaN where the parabola has no root in between.
Guess quadratic_root(const Value& a, const Value& b, const Value& c) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Newton's form: g(t) = a.g + d1 (t - a.t) + d2 (t - a.t)(t - b.t).
  const double d1 = (b.g - a.g) / (b.t - a.t);
  const double d2 = ((c.g - b.g) / (c.t - b.t) - d1) / (c.t - a.t);
  if (!std::isfinite(d2)) return {nan, nan};
  // In s = t - a.t, h = b.t - a.t: d2 s^2 + (d1 - d2 h) s + a.g = 0.
  const double h = b.t - a.t, p = d1 - d2 * h;
  double s;
  if (std::abs(d2) * h < 1e-12 * std::abs(p)) {
    s = -a.g / p;
  } else {
    const double disc = p * p - 4.0 * d2 * a.g;
    if (!(disc >= 0.0)) return {nan, nan};
    const double q = -0.5 * (p + std::copysign(std::sqrt(disc), p));
    const double s1 = q / d2, s2 = a.g / q;
    s = (s1 > 0.0 && s1 < h) ? s1 : s2;
  }
  if (!(s > 0.0 && s < h)) return {nan, nan};
  return {a.t + s, p + 2.0 * d2 * s};
}

// A bound already weighed on a window: how far F may bend towards T over it, and whether it
// is the window's own (not the quicker, larger one).
struct Bend {
  double value = std::numeric_limits<double>::quiet_NaN();
  bool exact = false;
};

class Marcher {
 public:
  // `want_gradient`: the first root's gradient is wanted (the hit's normal); see root_gradient.
  // `near_hit`, `start`: as march_cluster takes them.
  Marcher(const Impl& s, ClusterField& field, RootMode mode, bool want_gradient,
          std::vector<double>& out, TraceStats& stats, NearHit* near_hit,
          const NearHit* start)
      : s_(s), field_(field), mode_(mode), want_gradient_(want_gradient), out_(out),
        stats_(stats), near_hit_(near_hit), start_(start) {}

  // Whether the search is over (a root found where one is enough). `at_cluster_entry`: `from`
  // is where the ray enters the cluster's first support.
  bool march(double from, double to, bool at_cluster_entry);
  double last_root() const { return last_root_; }
  // The exact gradient at the last root, where its polish evaluated it (RootMode::first with
  // `want_gradient`): within the root tolerance of last_root().
  const std::optional<Vec3>& root_gradient() const { return root_gradient_; }
  // RootMode::any: the sample of the last bracket that lies inside (F >= T).
  double inside() const { return inside_; }

 private:
  Value value(double t) { return {t, field_.value_minus_threshold(t)}; }
  // The same, where the march's step ends: at or past the cluster's end, where every
  // support has ended, F = 0 < T without an evaluation (as at the cluster's entry).
  Value sample_towards(double t) {
    return t >= field_.reach() ? Value{t, -1.0} : value(t);
  }
  // The march's first point inside the cluster: the near-hit bound where it holds F below T
  // (near_hit.hpp), else a sample. With the bound, `slope` is F's rate there from the near
  // hit's gradient (per unit t, as Value's g), for the first step's prediction.
  Value first_value(double t, double& slope);
  bool bracket(const Value& a, const Value& b, const Value* third = nullptr);
  // The root along the ray of the tangent plane at `hit` (kTangentReach), with the slope
  // there; NaN where the ray passes further off or does not climb that plane's field.
  Guess tangent_root(const NearHit& hit) const;
  double polish_with_gradient(const Value& a, const Value& b, double t, double tolerance);
  bool search_window(const Value& a, const Value& b, Bend known = {});
  // How far F may bend away from its chord towards T over [a, b] (a on the side of `g`);
  // `quick`: a larger bound that costs less (ClusterField::curvature's `anywhere`), which
  // exists only below T (how far F bends down); above T it is the window's own bound.
  double bend_towards_threshold(double a, double b, double g, bool quick = false) const {
    return field_.curvature(a, b, !(g < 0.0), quick);
  }
  static bool has_quick_bound(double g) { return g < 0.0; }
  struct Step {
    double length;
    Bend bend;  // weighed over [a, a + length] (not for the shortest window)
  };
  Step step_from(const Value& a, double to, double min_step, double max_step,
                 double slope) const;

  const Impl& s_;
  ClusterField& field_;
  RootMode mode_;
  bool want_gradient_;
  std::vector<double>& out_;
  TraceStats& stats_;
  double last_root_ = kInfinity;
  double inside_ = kInfinity;
  std::optional<Vec3> root_gradient_;
  NearHit* near_hit_;
  const NearHit* start_;
};

// A sign change between a and b: its root, refined on the exact field (for RootMode::any a
// point of the bracket is enough).
bool Marcher::bracket(const Value& a, const Value& b, const Value* third) {
  double t = b.t;
  if (mode_ != RootMode::any) {
    ++stats_.roots;
    Guess guess{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    if (third) guess = quadratic_root(a, b, *third);
    if (mode_ == RootMode::first && start_ && a.g < 0.0) {
      const Guess near = tangent_root(*start_);
      if (near.t > a.t && near.t < b.t) guess = near;
    }
    const double tolerance = kRootTolerance * s_.min_radius;
    // A first hit's normal evaluates the gradient at the root anyway: the refiner leaves its
    // last point unevaluated, and that evaluation closes the root instead.
    const bool with_gradient = mode_ == RootMode::first && want_gradient_;
    t = refine_bracket(a.t, b.t, a.g, b.g,
                       [&](double x) { return field_.value_minus_threshold(x); }, guess.t,
                       guess.slope, tolerance, 0.0, !with_gradient, kLanding * s_.min_radius);
    if (with_gradient) t = polish_with_gradient(a, b, t, tolerance);
  } else {
    inside_ = a.g < 0.0 ? b.t : a.t;
  }
  if (out_.empty() || t > out_.back() + 1e-9 * s_.min_radius) out_.push_back(t);
  last_root_ = t;
  return mode_ != RootMode::all;
}

Guess Marcher::tangent_root(const NearHit& hit) const {
  const Ray& ray = field_.ray();
  const double slope = glm::dot(hit.gradient, ray.direction);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Vec3 w = hit.point - ray.origin;
  const double along = glm::dot(w, ray.direction), reach = kTangentReach * s_.min_radius;
  if (!(slope > 0.0) || !(glm::dot(w, w) - along * along <= reach * reach)) return {nan, nan};
  const double t =
      (s_.threshold - hit.value - glm::dot(hit.gradient, ray.origin - hit.point)) / slope;
  return {t, slope / s_.threshold};
}

// t: the refiner's landing point, left unevaluated (kLanding). One evaluation with the
// gradient gives the normal and a last Newton step, whose error is about (F'' / 2 F') step^2,
// with F'' / 2 from the parabola through the window's ends and t; the step is taken where ten
// times that is within the tolerance. Otherwise (rare) t was not as close as it looked: the
// bracket is then closed as the refiner always does, and the normal evaluated at its root
// afterwards.
double Marcher::polish_with_gradient(const Value& a, const Value& b, double t, double tolerance) {
  const field::FieldSample at = field_.sample(t);
  const double slope = glm::dot(at.gradient, field_.ray().direction) / s_.threshold;
  const double g = at.value / s_.threshold - 1.0, step = g / slope;
  const double d2 = ((g - a.g) / (t - a.t) - (b.g - g) / (b.t - t)) / (a.t - b.t);
  const bool converged = std::abs(step) <= tolerance ||
                         (std::abs(step) <= 4.0 * kLanding * s_.min_radius &&
                          10.0 * std::abs(d2 / slope) * step * step <= tolerance);
  if (converged && t - step > a.t && t - step < b.t) {
    root_gradient_ = at.gradient;
    if (near_hit_) {
      *near_hit_ = {field_.ray().at(t), at.value, at.gradient, 2.0 * field_.bend_bound_at(t)};
    }
    return t - step;
  }
  root_gradient_.reset();
  return refine_bracket(a.t, b.t, a.g, b.g,
                        [&](double x) { return field_.value_minus_threshold(x); }, t,
                        std::numeric_limits<double>::quiet_NaN(), tolerance);
}

// Where to sample a window whose chord bound reaches T: where that bound comes closest to
// T, kept within the window's middle half.
double split_point(const Value& a, const Value& b, double bend) {
  const double h = b.t - a.t;
  if (!(bend > 0.0)) return a.t + 0.5 * h;
  const double sign = a.g < 0.0 ? 1.0 : -1.0;
  const double s = 0.5 * h + sign * (b.g - a.g) / (bend * h);
  return a.t + std::clamp(s, 0.25 * h, 0.75 * h);
}

// a and b on the same side of T: split until the chord bound excludes a crossing pair, or
// the window is narrower than the resolution. `known`: a bound step_from weighed on this very
// window, tried before any other.
bool Marcher::search_window(const Value& a, const Value& b, Bend known) {
  double last_bend = known.value;  // the smallest bound weighed: where to sample next
  const auto excluded = [&](bool quick) {
    last_bend = bend_towards_threshold(a.t, b.t, a.g, quick);
    return chord_excluded(a, b, last_bend);
  };
  const bool weighed = known.value >= 0.0;
  if (weighed && chord_excluded(a, b, known.value)) return false;
  // A bound that failed is not weighed again: the window's own bound is the smaller one.
  const bool try_quick = has_quick_bound(a.g) && !weighed;
  const bool try_own = !(weighed && known.exact);
  if ((try_quick && excluded(true)) || (try_own && excluded(false))) {
    return false;
  }
  if (b.t - a.t < kResolution * s_.min_radius) return false;
  ++stats_.subdivisions;
  const Value mid = value(split_point(a, b, last_bend));
  if ((mid.g < 0.0) != (a.g < 0.0)) {
    if (bracket(a, mid, &b)) return true;
    return bracket(mid, b, &a);
  }
  if (search_window(a, mid)) return true;
  return search_window(mid, b);
}

// The next window from a: the longest, doubling from min_step up to max_step, over which
// the chord bound would exclude T if F came back to a's value at its end (the sum of each
// primitive's bound over its whole line is tried first: it costs nothing per window), or,
// where F moves away from T (`slope`, the last window's chord, NaN for the first), if F ended
// it where that chord points: a ray leaving a surface (every lit shadow ray) takes longer
// windows as F falls. (Trusting the chord towards T as well, landing past the crossing it
// predicts, cost 3-5 % more instructions: more windows were halved.) The bound that let the
// longest window through comes with it: search_window's first test on the same window.
Marcher::Step Marcher::step_from(const Value& a, double to, double min_step,
                                 double max_step, double slope) const {
  const double gap = std::abs(a.g);
  // The shortest window is taken whatever its bound says (search_window splits it if need
  // be), so the doubling starts from there without weighing it.
  Step best{min_step, {}};
  if (min_step >= max_step || a.t + min_step >= to) return best;
  // The quick bound only grows with the window: once it fails it is not asked again, the
  // window's own bound is (a receding prediction might let a longer window pass it after
  // all; the own bound, smaller, is then asked instead).
  bool quick_may_fit = has_quick_bound(a.g);
  // Where F moves towards T (or no chord is known yet) only the bound itself can let a window
  // through, and each bound grows with the window (more members, each one's bound over a
  // longer window at least as large): one that already fails times the next window's square
  // is not weighed again.
  const bool predicts = slope * a.g > 0.0;
  double last_quick = 0.0, last_own = 0.0;
  const auto fails_anyway = [&](double last, double window) {
    return !predicts && last * window * window >= 8.0 * gap;
  };
  for (double window = std::min(2.0 * min_step, max_step);;
       window = std::min(2.0 * window, max_step)) {
    const double end = std::min(to, a.t + window);
    Bend bend;
    const auto fits = [&](bool quick) {
      bend = {bend_towards_threshold(a.t, end, a.g, quick), !quick};
      (quick ? last_quick : last_own) = bend.value;
      if (bend.value * window * window < 8.0 * gap) return true;
      if (!predicts) return false;  // F moves away from T (on either side)
      // A prediction, not a bound (the chord bound is checked on the real sample): F >= 0
      // where strengths are positive, so it falls no further than g = -1.
      return chord_excluded(a, {end, std::max(-1.0, a.g + slope * (end - a.t))}, bend.value);
    };
    if (quick_may_fit && (fails_anyway(last_quick, window) || !fits(true))) quick_may_fit = false;
    if (!quick_may_fit && (fails_anyway(last_own, window) || !fits(false))) return best;
    best = {window, bend};
    if (window >= max_step || end >= to) return best;
  }
}

Value Marcher::first_value(double t, double& slope) {
  if (start_ && mode_ == RootMode::any && start_->bend >= 0.0) {
    const Vec3 x = field_.ray().at(t);
    const double reach = kNearHitReach * s_.min_radius;
    if (glm::dot(x - start_->point, x - start_->point) <= reach * reach) {
      const double bound = field_bound_near(*start_, x, 2.0 * field_.bend_bound_at(t));
      if (bound < s_.threshold) {
        slope = glm::dot(start_->gradient, field_.ray().direction) / s_.threshold;
        return {t, bound / s_.threshold - 1.0};
      }
    }
  }
  return value(t);
}

bool Marcher::march(double from, double to, bool at_cluster_entry) {
  const double min_step = kMinStep * s_.min_radius, max_step = kMaxStep * s_.min_radius;
  // Where the ray enters the cluster's first support, every field of the cluster is zero
  // (each kernel vanishes at its support's edge, and no other support has begun): F = 0 < T,
  // known without an evaluation.
  // The first step's chord: none yet, or the rate where the ray leaves a near hit.
  double first_slope = std::numeric_limits<double>::quiet_NaN();
  Value a = at_cluster_entry ? Value{from, -1.0} : first_value(from, first_slope);
  if (a.g == 0.0 && bracket(a, a)) return true;
  // Whether there is a root at all (a shadow ray), in a cluster the ray enters from outside
  // (not the one it starts in, whose field falls away from the surface it leaves): one
  // sample in the middle, where a ray through a sheet of triangles crosses it and the field
  // is highest, settles most blocked rays without a window (F >= T there and F = 0 at the
  // entry: a root between them).
  if (mode_ == RootMode::any && at_cluster_entry) {
    const Value middle = value(0.5 * (from + to));
    if (middle.g >= 0.0 && bracket(a, middle)) return true;
  }
  Value before = a;
  bool have_before = false;
  while (a.t < to) {
    ++stats_.fits;
    const double slope = have_before ? (a.g - before.g) / (a.t - before.t) : first_slope;
    const Step step = step_from(a, to, min_step, max_step, slope);
    const Value b = sample_towards(std::min(to, a.t + step.length));
    if ((a.g < 0.0) != (b.g < 0.0)) {
      if (bracket(a, b, have_before ? &before : nullptr)) return true;
    } else if (search_window(a, b, step.bend)) {
      return true;
    }
    before = a;
    have_before = true;
    a = b;
  }
  return false;
}

// The largest ball certified inside the surface around kProbePoints points from `from` (a
// sample inside) on, up to `to`, each sampled with its gradient on the cluster's members
// (which hold every support that holds a point of the ray there).
InsideBall probe_inside(const Impl& s, ClusterField& field, double from, double to) {
  InsideBall best;
  if (!s.nonnegative) return best;
  for (int k = 0; k < kProbePoints; ++k) {
    const double t = from + k * kProbeStep * s.min_radius;
    if (t > to) break;
    const field::FieldSample at = field.sample(t);
    const double radius =
        inside_radius(at.value, s.threshold, glm::length(at.gradient), field.bend_bound_at(t));
    if (radius > best.radius) {
      best = {field.ray().at(t), radius};
    } else if (radius == 0.0 && k > 0) {
      break;  // out again: the deepest point is behind
    }
  }
  return best;
}

}  // namespace

void march_cluster(const Impl& surface, const Ray& ray,
                   std::span<const accel::SupportInterval> cluster,
                   const accel::TriangleLineTable& lines, double tmin, double tmax,
                   RootMode mode, std::vector<double>& out, TraceStats& stats,
                   std::optional<Vec3>* first_gradient, InsideBall* inside, NearHit* near_hit,
                   const NearHit* start) {
  const double from = std::max(tmin, cluster.front().enter);
  ClusterField field(surface, ray, cluster, lines, from, mode, stats);
  const double to = std::min(tmax, field.reach());
  if (!(from < to)) return;
  Marcher marcher(surface, field, mode, first_gradient != nullptr, out, stats,
                  mode == RootMode::first ? near_hit : nullptr, start);
  if (!marcher.march(from, to, from == cluster.front().enter)) return;
  if (mode == RootMode::first && first_gradient) {
    if (marcher.root_gradient()) {
      *first_gradient = *marcher.root_gradient();
    } else {
      const double t = marcher.last_root();
      const field::FieldSample at = field.sample(t);
      *first_gradient = at.gradient;
      if (near_hit) *near_hit = {ray.at(t), at.value, at.gradient, 2.0 * field.bend_bound_at(t)};
    }
  }
  if (mode == RootMode::any && inside) *inside = probe_inside(surface, field, marcher.inside(), to);
}

}  // namespace convray::implicit
