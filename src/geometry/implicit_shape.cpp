#include "geometry/implicit_shape.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "field/arc.hpp"
#include "field/blob.hpp"
#include "field/point.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "core/box.hpp"
#include "scene/texture_opacity.hpp"

namespace convray::geometry {

using Kind = scene::Implicit::Kind;

namespace {

// POV-Ray's blob counts points within this of the threshold as inside.
constexpr double kBlobInsideTolerance = 1e-6;

size_t component_count(const scene::ConvolutionObject& o, Kind kind) {
  switch (kind) {
    case Kind::mesh:
      return o.meshes.size();
    case Kind::segment:
      return o.segments.size();
    case Kind::arc:
      return o.arcs.size();
    case Kind::point:
      return o.points.size();
    case Kind::blob_sphere:
      return o.blob_spheres.size();
    case Kind::blob_cylinder:
      return o.blob_cylinders.size();
  }
  return 0;
}

}  // namespace

ImplicitShape::ImplicitShape(const scene::Implicit& record, SurfaceInfoPtr surface,
                             implicit::SupportCache* cache, implicit::Tracer tracer)
    : surface_(implicit::make_surface(record.object, cache, tracer)),
      is_blob_(record.is_blob),
      object_surface_(std::move(surface)) {
  if (!record.component_textures.empty()) index_components(record);
  const auto blocks = [](const SurfaceInfoPtr& info) {
    return info && !info->no_shadow && info->texture && scene::always_opaque(*info->texture);
  };
  blocks_light_ = blocks(object_surface_) &&
                  std::all_of(component_surfaces_.begin(), component_surfaces_.end(), blocks);
}

void ImplicitShape::index_components(const scene::Implicit& record) {
  const scene::ConvolutionObject& object = record.object;
  surface_of_.resize(6);
  for (int k = 0; k < 6; ++k) {
    surface_of_[size_t(k)].assign(component_count(object, Kind(k)), object_surface_.get());
  }
  for (const scene::ComponentTexture& given : record.component_textures) {
    if (given.index >= record.component_order.size()) {
      throw std::invalid_argument("component texture for component " + std::to_string(given.index) +
                                  ", which does not exist");
    }
    const auto [kind, index] = record.component_order[given.index];
    if (index >= component_count(object, kind)) {
      throw std::invalid_argument("component order names a missing component");
    }
    auto info = std::make_shared<SurfaceInfo>(*object_surface_);
    if (given.texture) info->texture = given.texture;
    component_surfaces_.push_back(info);
    surface_of_[size_t(kind)][index] = info.get();
  }
}

const SurfaceInfo* ImplicitShape::surface_at(const Vec3& p) const {
  if (surface_of_.empty()) return object_surface_.get();
  thread_local std::vector<implicit::ComponentValue> values;
  thread_local std::vector<implicit::ComponentValue> sums;
  values.clear();
  sums.clear();
  surface_->component_values(p, values);
  // Few components reach any one point (a mesh's many triangles are one component).
  for (const auto& v : values) {
    auto it = std::find_if(sums.begin(), sums.end(),
                           [&](const auto& s) { return s.component == v.component; });
    if (it == sums.end()) {
      sums.push_back(v);
    } else {
      it->value += v.value;
    }
  }
  const SurfaceInfo* dominant = object_surface_.get();
  double largest = 0.0;
  for (const auto& s : sums) {
    if (s.value > largest) {
      largest = s.value;
      dominant = surface_of_[size_t(s.component.kind)][s.component.index];
    }
  }
  return dominant;
}

Box3 ImplicitShape::bounds() const { return surface_->bounds(); }

void ImplicitShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                              TraceStats& stats) const {
  // Crossings are searched where the field can be non-zero; the support box is wider than the
  // surface, so no smooth crossing sits on its faces.
  double t0 = tmin, t1 = tmax;
  if (!clip_to_box(ray, surface_->bounds(), t0, t1)) return;
  thread_local std::vector<SurfaceHit> hits;  // not re-entered: hits() calls no shape
  hits.clear();
  surface_->hits(ray, t0, t1, hits, stats);
  for (const SurfaceHit& hit : hits) {
    if (hit.t > tmin && hit.t < tmax) out.push_back({hit.t, hit.normal, surface_at(hit.point)});
  }
}

std::optional<Crossing> ImplicitShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                      TraceStats& stats) const {
  // The surface searches the closed interval, so a crossing on one of its ends sends us to
  // the full list for the next one.
  double t0 = tmin, t1 = tmax;
  if (!clip_to_box(ray, surface_->bounds(), t0, t1)) return std::nullopt;
  const auto hit = surface_->first_hit(ray, t0, t1, stats);
  if (!hit) return std::nullopt;
  if (hit->t > tmin && hit->t < tmax) return Crossing{hit->t, hit->normal, surface_at(hit->point)};
  std::vector<Crossing> all;
  crossings(ray, tmin, tmax, all, stats);
  if (all.empty()) return std::nullopt;
  return all.front();
}

bool ImplicitShape::any_crossing(const Ray& ray, double tmin, double tmax,
                                 TraceStats& stats) const {
  double t0 = tmin, t1 = tmax;
  if (!clip_to_box(ray, surface_->bounds(), t0, t1)) return false;
  return surface_->occluded(ray, t0, t1, stats);
}

bool ImplicitShape::inside(const Vec3& p) const {
  const double value = surface_->field(p).value;
  const double threshold = surface_->threshold();
  return is_blob_ ? value > threshold - kBlobInsideTolerance : value >= threshold;
}

}  // namespace convray::geometry
