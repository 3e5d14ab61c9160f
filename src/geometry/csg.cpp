#include "geometry/csg.hpp"

#include <algorithm>
#include <stdexcept>

#include "geometry/bounds.hpp"

namespace convray::geometry {

using scene::CsgOperation;

CsgShape::CsgShape(CsgOperation operation, std::vector<ShapePtr> children)
    : operation_(operation), children_(std::move(children)) {
  Box3 surfaces;                // the hull of the children's surfaces
  Box3 reach = infinite_box();  // where every child's surface or inside may be
  Box3 insides;                 // the hull of the children's insides
  Box3 common_inside = infinite_box();
  for (const ShapePtr& child : children_) {
    const Box3 b = child->bounds(), ib = child->inside_bounds();
    child_bounds_.push_back(b);
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
          children_.empty() ? Box3{} : hull(child_bounds_[0], children_[0]->inside_bounds());
      bounds_ = overlap(surfaces, first);
      inside_bounds_ = children_.empty() ? Box3{} : children_[0]->inside_bounds();
      break;
    }
  }
  if (is_empty(bounds_)) bounds_ = Box3{};
  if (is_empty(inside_bounds_)) inside_bounds_ = Box3{};
}

Box3 CsgShape::bounds() const { return bounds_; }
Box3 CsgShape::inside_bounds() const { return inside_bounds_; }

bool CsgShape::keeps(size_t from, const Vec3& p) const {
  for (size_t j = 0; j < children_.size(); ++j) {
    if (j == from) continue;
    switch (operation_) {
      case CsgOperation::union_:
        return true;
      case CsgOperation::merge:
        if (children_[j]->inside(p)) return false;
        break;
      case CsgOperation::intersection:
        if (!children_[j]->inside(p)) return false;
        break;
      case CsgOperation::difference:
        // Inside the first child, outside every other.
        if ((j == 0) != children_[j]->inside(p)) return false;
        break;
    }
  }
  return true;
}

bool CsgShape::inside(const Vec3& p) const {
  switch (operation_) {
    case CsgOperation::union_:
    case CsgOperation::merge:
      return std::any_of(children_.begin(), children_.end(),
                         [&](const ShapePtr& c) { return c->inside(p); });
    case CsgOperation::intersection:
      return !children_.empty() && std::all_of(children_.begin(), children_.end(),
                                               [&](const ShapePtr& c) { return c->inside(p); });
    case CsgOperation::difference:
      if (children_.empty() || !children_[0]->inside(p)) return false;
      return std::none_of(children_.begin() + 1, children_.end(),
                          [&](const ShapePtr& c) { return c->inside(p); });
  }
  return false;
}

bool CsgShape::meets(const Ray& ray, double tmin, double tmax) const {
  // A test only: narrowing the interval to the box would drop crossings on its faces.
  return clip_to_box(ray, bounds_, tmin, tmax);
}

void CsgShape::child_crossings(const Ray& ray, double tmin, double tmax,
                               std::vector<std::pair<Crossing, size_t>>& out,
                               TraceStats& stats) const {
  // Not thread_local scratch: a child may be a CSG that gathers its own children here too.
  std::vector<Crossing> found;
  for (size_t i = 0; i < children_.size(); ++i) {
    double t0 = tmin, t1 = tmax;
    if (!clip_to_box(ray, child_bounds_[i], t0, t1)) continue;
    found.clear();
    children_[i]->crossings(ray, tmin, tmax, found, stats);
    for (const Crossing& c : found) out.emplace_back(c, i);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& a, const auto& b) { return a.first.t < b.first.t; });
}

void CsgShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                         TraceStats& stats) const {
  if (!meets(ray, tmin, tmax)) return;
  std::vector<std::pair<Crossing, size_t>> candidates;
  child_crossings(ray, tmin, tmax, candidates, stats);
  for (auto& [crossing, child] : candidates) {
    if (!keeps(child, ray.at(crossing.t))) continue;
    if (operation_ == CsgOperation::difference && child > 0) crossing.normal = -crossing.normal;
    out.push_back(crossing);
  }
}

std::optional<Crossing> CsgShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                 TraceStats& stats) const {
  if (!meets(ray, tmin, tmax)) return std::nullopt;
  if (operation_ == CsgOperation::union_) {
    // Every crossing counts: the nearest of the children's first ones.
    std::optional<Crossing> nearest;
    for (size_t i = 0; i < children_.size(); ++i) {
      double t0 = tmin, t1 = tmax;
      if (!clip_to_box(ray, child_bounds_[i], t0, t1)) continue;
      if (auto c = children_[i]->first_crossing(ray, tmin, tmax, stats)) {
        nearest = c;
        tmax = c->t;
      }
    }
    return nearest;
  }
  std::vector<Crossing> all;
  crossings(ray, tmin, tmax, all, stats);
  if (all.empty()) return std::nullopt;
  return all.front();
}

}  // namespace convray::geometry
