#include "geometry/csg.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"

namespace convray::geometry {

using scene::CsgOperation;

namespace {

// Children per leaf: a handful keeps small CSGs (the usual two or three children) a single
// leaf, asked in order as a plain loop would.
constexpr int kLeafSize = 4;

}  // namespace

CsgShape::CsgShape(CsgOperation operation, std::vector<ShapePtr> children)
    : operation_(operation), children_(std::move(children)) {
  Box3 surfaces;                // the hull of the children's surfaces
  Box3 reach = infinite_box();  // where every child's surface or inside may be
  Box3 insides;                 // the hull of the children's insides
  Box3 common_inside = infinite_box();
  for (const ShapePtr& child : children_) {
    const Box3 b = child->bounds(), ib = child->inside_bounds();
    child_bounds_.push_back(b);
    child_inside_bounds_.push_back(ib);
    surfaces = hull(surfaces, b);
    reach = overlap(reach, hull(b, ib));
    insides = hull(insides, ib);
    common_inside = overlap(common_inside, ib);
  }
  switch (operation_) {
    case CsgOperation::union_:
    case CsgOperation::merge:
      bounds_ = surfaces;
      inside_bounds_ = insides;
      break;
    case CsgOperation::intersection:
      // A kept crossing lies on one child and inside (or on) every other.
      bounds_ = children_.empty() ? Box3{} : overlap(surfaces, reach);
      inside_bounds_ = children_.empty() ? Box3{} : common_inside;
      break;
    case CsgOperation::difference: {
      // A kept crossing lies on the first child or inside it.
      const Box3 first =
          children_.empty() ? Box3{} : hull(child_bounds_[0], child_inside_bounds_[0]);
      bounds_ = overlap(surfaces, first);
      inside_bounds_ = children_.empty() ? Box3{} : child_inside_bounds_[0];
      break;
    }
  }
  if (is_empty(bounds_)) bounds_ = Box3{};
  if (is_empty(inside_bounds_)) inside_bounds_ = Box3{};
  build_indexes();
}

void CsgShape::build_indexes() {
  auto index = [](const std::vector<Box3>& boxes, Index& into) {
    std::vector<Box3> finite;
    for (size_t i = 0; i < boxes.size(); ++i) {
      if (is_empty(boxes[i])) continue;  // nothing there: never met, never inside
      if (is_finite(boxes[i])) {
        into.bounded.push_back(uint32_t(i));
        finite.push_back(padded(boxes[i]));
      } else {
        into.unbounded.push_back(uint32_t(i));
      }
    }
    into.bvh = Bvh(finite, kLeafSize);
  };
  index(child_bounds_, surfaces_);
  index(child_inside_bounds_, insides_);
  // The inside tests compare points with the padded boxes: rounding never drops a child.
  for (Box3& box : child_inside_bounds_) {
    if (is_finite(box)) box = padded(box);
  }
}

Box3 CsgShape::bounds() const { return bounds_; }
Box3 CsgShape::inside_bounds() const { return inside_bounds_; }

bool CsgShape::inside_other(const Vec3& p, size_t skip1, size_t skip2) const {
  auto test = [&](uint32_t child) {
    return child != skip1 && child != skip2 && contains(child_inside_bounds_[child], p) &&
           children_[child]->inside(p);
  };
  for (uint32_t child : insides_.unbounded) {
    if (test(child)) return true;
  }
  return insides_.bvh.any_at(p, [&](uint32_t k) { return test(insides_.bounded[k]); });
}

bool CsgShape::keeps(size_t from, const Vec3& p) const {
  constexpr size_t kNone = size_t(-1);
  switch (operation_) {
    case CsgOperation::union_:
      return true;
    case CsgOperation::merge:
      return !inside_other(p, from, kNone);
    case CsgOperation::intersection:
      // Inside every other child: each must be asked (a box that misses p settles it).
      for (size_t j = 0; j < children_.size(); ++j) {
        if (j == from) continue;
        if (!contains(child_inside_bounds_[j], p) || !children_[j]->inside(p)) return false;
      }
      return true;
    case CsgOperation::difference:
      // Inside the first child, outside every other.
      if (from != 0 && !children_[0]->inside(p)) return false;
      return !inside_other(p, 0, from);
  }
  return false;
}

bool CsgShape::inside(const Vec3& p) const {
  constexpr size_t kNone = size_t(-1);
  if (children_.empty()) return false;
  switch (operation_) {
    case CsgOperation::union_:
    case CsgOperation::merge:
      return inside_other(p, kNone, kNone);
    case CsgOperation::intersection:
      return keeps(size_t(-1), p);
    case CsgOperation::difference:
      return children_[0]->inside(p) && !inside_other(p, 0, kNone);
  }
  return false;
}

bool CsgShape::meets(const Ray& ray, double tmin, double tmax) const {
  // A test only: narrowing the interval to the box would drop crossings on its faces.
  return clip_to_box(ray, bounds_, tmin, tmax);
}

void CsgShape::child_crossings(const Ray& ray, double tmin, double tmax,
                               std::vector<Candidate>& out, TraceStats& stats) const {
  // Not thread_local scratch: a child may be a CSG that gathers its own children here too.
  std::vector<Crossing> found;
  auto ask = [&](uint32_t child) {
    double t0 = tmin, t1 = tmax;
    if (!clip_to_box(ray, child_bounds_[child], t0, t1)) return;
    found.clear();
    children_[child]->crossings(ray, tmin, tmax, found, stats);
    for (const Crossing& c : found) out.push_back({c, child});
  };
  for (uint32_t child : surfaces_.unbounded) ask(child);
  double reach = tmax;
  surfaces_.bvh.traverse(ray, tmin, reach, [&](uint32_t k, double&) { ask(surfaces_.bounded[k]); });
  // The hierarchy visits children out of order: ties go to the earlier child, as in a loop.
  std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
    return a.crossing.t < b.crossing.t || (a.crossing.t == b.crossing.t && a.child < b.child);
  });
}

// A child's crossing as the CSG's own, or nothing where the operation drops it (a subtracted
// child's surface faces the other way).
std::optional<Crossing> CsgShape::kept_crossing(const Candidate& candidate, const Ray& ray) const {
  if (!keeps(candidate.child, ray.at(candidate.crossing.t))) return std::nullopt;
  Crossing crossing = candidate.crossing;
  if (operation_ == CsgOperation::difference && candidate.child > 0) {
    crossing.normal = -crossing.normal;
  }
  return crossing;
}

void CsgShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                         TraceStats& stats) const {
  if (!meets(ray, tmin, tmax)) return;
  std::vector<Candidate> candidates;
  child_crossings(ray, tmin, tmax, candidates, stats);
  for (const Candidate& candidate : candidates) {
    if (auto kept = kept_crossing(candidate, ray)) out.push_back(*kept);
  }
}

std::optional<Crossing> CsgShape::first_of_union(const Ray& ray, double tmin, double tmax,
                                                 TraceStats& stats) const {
  // Every crossing counts: the nearest of the children's first ones, the ray shortened by
  // each one found (ties: the earlier child, as in a loop).
  std::optional<Crossing> nearest;
  size_t nearest_child = 0;
  auto ask = [&](uint32_t child, double& limit) {
    double t0 = tmin, t1 = limit;
    if (!clip_to_box(ray, child_bounds_[child], t0, t1)) return;
    const double reach = nearest && child < nearest_child ? std::nextafter(limit, kInfinity) : limit;
    if (auto c = children_[child]->first_crossing(ray, tmin, reach, stats)) {
      nearest = c;
      nearest_child = child;
      limit = c->t;
    }
  };
  double limit = tmax;
  for (uint32_t child : surfaces_.unbounded) ask(child, limit);
  surfaces_.bvh.traverse(ray, tmin, limit,
                         [&](uint32_t k, double& reach) { ask(surfaces_.bounded[k], reach); });
  return nearest;
}

std::optional<Crossing> CsgShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                 TraceStats& stats) const {
  if (!meets(ray, tmin, tmax)) return std::nullopt;
  if (operation_ == CsgOperation::union_) return first_of_union(ray, tmin, tmax, stats);
  // The candidates in order; the first one kept is the answer (later ones need no test).
  std::vector<Candidate> candidates;
  child_crossings(ray, tmin, tmax, candidates, stats);
  for (const Candidate& candidate : candidates) {
    if (auto kept = kept_crossing(candidate, ray)) return kept;
  }
  return std::nullopt;
}

}  // namespace convray::geometry
