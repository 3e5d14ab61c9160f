#include "geometry/world.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"
#include "core/bvh.hpp"
#include "geometry/instance.hpp"

namespace convray::geometry {
namespace {

void sort_by_distance(std::vector<Crossing>& crossings, size_t first) {
  std::stable_sort(crossings.begin() + std::ptrdiff_t(first), crossings.end(),
                   [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
}

// Drops the crossings of surfaces that cast no shadow (a no_shadow child of a CSG).
void drop_shadowless(std::vector<Crossing>& crossings, size_t first) {
  const auto removed =
      std::remove_if(crossings.begin() + std::ptrdiff_t(first), crossings.end(),
                     [](const Crossing& c) { return c.surface && c.surface->no_shadow; });
  crossings.erase(removed, crossings.end());
}

bool hidden_from(World::Viewer viewer, const SurfaceInfo* surface) {
  if (!surface || viewer == World::Viewer::any) return false;
  return viewer == World::Viewer::camera ? surface->no_image : surface->no_reflection;
}

// The first crossing of `shape` in (tmin, tmax) that `viewer` sees: a hidden surface is
// passed through (the ray goes on from just beyond it, as POV-Ray's does).
std::optional<Crossing> first_seen_crossing(const Shape& shape, const Ray& ray, double tmin,
                                            double tmax, TraceStats& stats,
                                            World::Viewer viewer) {
  std::optional<Crossing> c = shape.first_crossing(ray, tmin, tmax, stats);
  while (c && hidden_from(viewer, c->surface)) {
    const double beyond = c->t + 1e-9 * (1.0 + std::abs(c->t));
    c = shape.first_crossing(ray, beyond, tmax, stats);
  }
  return c;
}

}  // namespace

struct World::Index {
  Bvh bvh;                         // over the bounded objects' padded boxes
  std::vector<size_t> bounded;     // BVH primitive -> object
  std::vector<size_t> unbounded;   // objects always asked (planes, inverted solids, ...)
  std::vector<Box3> inside_boxes;  // each object's inside_bounds()
  Box3 bounds;                     // the union of the finite bounds
};

World::World(const scene::Scene& scene, implicit::SupportCache* cache, implicit::Tracer tracer) {
  auto index = std::make_unique<Index>();
  std::vector<Box3> boxes;
  std::vector<ShapePtr> built;
  SharedUnions shared;  // kept alive by the instances that use them
  for (const scene::ObjectPtr& object : scene.objects) {
    if (!object) continue;
    const size_t before = built.size();
    build_split_shapes(*object, built, cache, tracer, &shared);
    hollow_.resize(built.size(), object->hollow ? 1 : 0);
    if (!object->hollow) solids_ += built.size() - before;
  }
  for (ShapePtr& shape : built) {
    const Box3 box = shape->bounds();
    const size_t id = shapes_.size();
    index->inside_boxes.push_back(shape->inside_bounds());
    bounds_.push_back(box);
    blocks_light_.push_back(shape->blocks_light() ? 1 : 0);
    blockers_ += blocks_light_.back();
    shapes_.push_back(std::move(shape));
    if (is_empty(box)) continue;  // no surface at all: never hit
    if (is_finite(box)) {
      index->bounded.push_back(id);
      boxes.push_back(padded(box));
      index->bounds = hull(index->bounds, box);
    } else {
      index->unbounded.push_back(id);
    }
  }
  shared_unions_ = shared.unions();
  shared_members_ = shared.members();
  index->bvh = Bvh(boxes, 2);
  index_ = std::move(index);
}

World::~World() = default;
World::World(World&&) noexcept = default;

Box3 World::bounds() const { return index_->bounds; }

std::optional<Crossing> World::first_hit(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats, Objects objects,
                                         Viewer viewer) const {
  std::optional<Crossing> nearest;
  double reach = tmax;
  const bool skip_blockers = objects == Objects::letting_light_through;
  if (skip_blockers && blockers_ == shapes_.size()) return std::nullopt;
  auto ask = [&](size_t id, double& limit) {
    if (skip_blockers && blocks_light_[id]) return;
    if (auto c = first_seen_crossing(*shapes_[id], ray, tmin, limit, stats, viewer)) {
      nearest = c;
      limit = c->t;  // only nearer objects matter now
    }
  };
  for (size_t id : index_->unbounded) ask(id, reach);
  index_->bvh.traverse(ray, tmin, reach,
                       [&](uint32_t k, double& limit) { ask(index_->bounded[k], limit); });
  return nearest;
}

bool World::blocked(const Ray& ray, double tmin, double tmax, TraceStats& stats) const {
  if (blockers_ == 0) return false;  // most scenes: no second walk of the hierarchy
  bool found = false;
  auto ask = [&](size_t id, double& limit) {
    if (found || !blocks_light_[id]) return;
    if (shapes_[id]->any_crossing(ray, tmin, tmax, stats)) {
      found = true;
      limit = -kInfinity;  // ends the traversal
    }
  };
  double reach = tmax;
  for (size_t id : index_->unbounded) ask(id, reach);
  if (!found) index_->bvh.traverse(ray, tmin, reach, [&](uint32_t k, double& limit) {
    ask(index_->bounded[k], limit);
  });
  return found;
}

bool World::blocked_brute_force(const Ray& ray, double tmin, double tmax,
                                TraceStats& stats) const {
  for (size_t id = 0; id < shapes_.size(); ++id) {
    if (!blocks_light_[id]) continue;
    if (shapes_[id]->first_crossing(ray, tmin, tmax, stats)) return true;
  }
  return false;
}

std::optional<Crossing> World::first_hit_brute_force(const Ray& ray, double tmin, double tmax,
                                                     TraceStats& stats) const {
  std::optional<Crossing> nearest;
  for (const ShapePtr& shape : shapes_) {
    if (auto c = shape->first_crossing(ray, tmin, tmax, stats)) {
      nearest = c;
      tmax = c->t;
    }
  }
  return nearest;
}

void World::shadow_crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                             TraceStats& stats) const {
  const size_t first = out.size();
  for (size_t id : index_->unbounded) shapes_[id]->crossings(ray, tmin, tmax, out, stats);
  double reach = tmax;
  index_->bvh.traverse(ray, tmin, reach, [&](uint32_t k, double&) {
    shapes_[index_->bounded[k]]->crossings(ray, tmin, tmax, out, stats);
  });
  drop_shadowless(out, first);
  sort_by_distance(out, first);
}

void World::shadow_crossings_brute_force(const Ray& ray, double tmin, double tmax,
                                         std::vector<Crossing>& out, TraceStats& stats) const {
  const size_t first = out.size();
  for (const ShapePtr& shape : shapes_) shape->crossings(ray, tmin, tmax, out, stats);
  drop_shadowless(out, first);
  sort_by_distance(out, first);
}

bool World::inside_solid(const Vec3& p) const {
  if (solids_ == 0) return false;
  for (size_t id = 0; id < shapes_.size(); ++id) {
    if (hollow_[id]) continue;
    if (contains(index_->inside_boxes[id], p) && shapes_[id]->inside(p)) return true;
  }
  return false;
}

bool World::inside_any(const Vec3& p) const {
  for (size_t id = 0; id < shapes_.size(); ++id) {
    if (contains(index_->inside_boxes[id], p) && shapes_[id]->inside(p)) return true;
  }
  return false;
}

}  // namespace convray::geometry
