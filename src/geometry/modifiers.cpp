#include "geometry/modifiers.hpp"

#include <algorithm>

#include "core/box.hpp"

namespace convray::geometry {

// --- inverse ---

InvertedShape::InvertedShape(ShapePtr child) : child_(std::move(child)) {}

Box3 InvertedShape::bounds() const { return child_->bounds(); }  // the same surface
Box3 InvertedShape::inside_bounds() const { return infinite_box(); }

void InvertedShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                              TraceStats& stats) const {
  const size_t first = out.size();
  child_->crossings(ray, tmin, tmax, out, stats);
  for (size_t i = first; i < out.size(); ++i) out[i].normal = -out[i].normal;
}

std::optional<Crossing> InvertedShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                      TraceStats& stats) const {
  auto crossing = child_->first_crossing(ray, tmin, tmax, stats);
  if (crossing) crossing->normal = -crossing->normal;
  return crossing;
}

bool InvertedShape::inside(const Vec3& p) const { return !child_->inside(p); }

// --- clipped_by ---

ClippedShape::ClippedShape(ShapePtr shape, std::vector<ShapePtr> clips)
    : shape_(std::move(shape)), clips_(std::move(clips)) {
  // What is kept lies inside every clipping object.
  bounds_ = shape_->bounds();
  inside_bounds_ = shape_->inside_bounds();
  for (const ShapePtr& clip : clips_) {
    bounds_ = overlap(bounds_, clip->inside_bounds());
    inside_bounds_ = overlap(inside_bounds_, clip->inside_bounds());
  }
  if (is_empty(bounds_)) bounds_ = Box3{};
  if (is_empty(inside_bounds_)) inside_bounds_ = Box3{};
}

Box3 ClippedShape::bounds() const { return bounds_; }
Box3 ClippedShape::inside_bounds() const { return inside_bounds_; }

bool ClippedShape::inside_clips(const Vec3& p) const {
  return std::all_of(clips_.begin(), clips_.end(),
                     [&](const ShapePtr& clip) { return clip->inside(p); });
}

void ClippedShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                             TraceStats& stats) const {
  double t0 = tmin, t1 = tmax;
  if (!clip_to_box(ray, bounds_, t0, t1)) return;  // a test: never narrow to the box
  const size_t first = out.size();
  shape_->crossings(ray, tmin, tmax, out, stats);
  const auto removed =
      std::remove_if(out.begin() + std::ptrdiff_t(first), out.end(),
                     [&](const Crossing& c) { return !inside_clips(ray.at(c.t)); });
  out.erase(removed, out.end());
}

bool ClippedShape::inside(const Vec3& p) const { return shape_->inside(p) && inside_clips(p); }

// --- bounded_by ---

BoundedShape::BoundedShape(ShapePtr shape, const Shape& bound)
    : shape_(std::move(shape)), region_(hull(bound.bounds(), bound.inside_bounds())) {
  bounds_ = overlap(shape_->bounds(), region_);
  if (is_empty(bounds_)) bounds_ = Box3{};
}

Box3 BoundedShape::bounds() const { return bounds_; }
Box3 BoundedShape::inside_bounds() const { return shape_->inside_bounds(); }

void BoundedShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                             TraceStats& stats) const {
  double t0 = tmin, t1 = tmax;
  if (!clip_to_box(ray, region_, t0, t1)) return;
  shape_->crossings(ray, tmin, tmax, out, stats);
}

std::optional<Crossing> BoundedShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                     TraceStats& stats) const {
  double t0 = tmin, t1 = tmax;
  if (!clip_to_box(ray, region_, t0, t1)) return std::nullopt;
  return shape_->first_crossing(ray, tmin, tmax, stats);
}

bool BoundedShape::inside(const Vec3& p) const { return shape_->inside(p); }

}  // namespace convray::geometry
