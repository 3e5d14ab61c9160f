#include "implicit/cluster_field.hpp"

#include <algorithm>

namespace convray::implicit {

using Impl = ConvolutionSurface::Impl;

thread_local std::vector<ClusterField::Bending> ClusterField::members_;
thread_local DownBendTable ClusterField::down_;
thread_local std::vector<ClusterField::Member> ClusterField::others_;
thread_local std::vector<ClusterField::Batch> ClusterField::batches_;

ClusterField::ClusterField(const Impl& s, const Ray& ray,
                           std::span<const accel::SupportInterval> cluster,
                           const accel::TriangleLineTable& lines, double origin_t,
                           TraceStats& stats)
    : s_(s), ray_(ray), stats_(stats), cluster_(cluster), lines_(lines), origin_t_(origin_t) {
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
  b.group = &group;
  b.triangles.clear();
  b.enter.clear();
  b.exit.clear();
  b.inside_enter.clear();
  b.inside_exit.clear();
  b.quartics.clear();
  b.has_quartic.clear();
  b.lane_set.clear();
  // Lanes for as many members as the cluster has (most clusters meet one mesh): sized once.
  b.batch.resize_unset(cluster_.size());
  const size_t mask_size = cluster_.size() + kSimdWidth;  // value_of_range reads whole widths
  if (b.listed.size() < mask_size) b.listed.resize(mask_size);
  if (b.clipped_room.size() < cluster_.size()) {
    b.clipped_room.resize(cluster_.size());
    b.inside_room.resize(cluster_.size());
  }
  return b;
}

void ClusterField::add_triangle(Batch& b, uint32_t index, double enter, double exit,
                                const accel::Span& corners_within) {
  b.triangles.push_back(index);
  b.enter.push_back(enter);
  b.exit.push_back(exit);
  // Where all three corners are within R of p(t), shrunk by a hair, so rounding never takes a
  // corner just outside for inside.
  const double margin = 1e-9 * b.group->radius;
  b.inside_enter.push_back(corners_within.enter + margin);
  b.inside_exit.push_back(corners_within.exit - margin);
  b.quartics.emplace_back();
  b.has_quartic.push_back(0);
  b.lane_set.push_back(0);
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
  if (b.lane_set[lane]) return;
  const uint32_t triangle = b.triangles[lane];
  b.batch.set_lane(lane, s_.triangles[triangle], s_.frames[triangle]);
  b.lane_set[lane] = 1;
}

const field::LineQuartic& ClusterField::quartic(Batch& b, uint32_t lane) {
  if (!b.has_quartic[lane]) {
    const uint32_t triangle = b.triangles[lane];
    b.quartics[lane] =
        field::triangle_line_quartic(s_.triangles[triangle], s_.frames[triangle].area,
                                     ray_.at(origin_t_), ray_.direction, b.group->radius);
    b.has_quartic[lane] = 1;
  }
  return b.quartics[lane];
}

template <ClusterField::Want kWant>
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
    for (uint32_t lane = 0; lane < b.enter.size(); ++lane) {
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
      field::LineQuartic quartics;
      for (uint32_t lane : inside_lanes) quartics.add(quartic(b, lane), 1.0);
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
    for (size_t lane = 0; lane < b.enter.size(); ++lane) {
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

}  // namespace convray::implicit
