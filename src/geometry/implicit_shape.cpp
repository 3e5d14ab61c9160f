#include "geometry/implicit_shape.hpp"

#include <stdexcept>
#include <string>

#include "field/arc.hpp"
#include "field/blob.hpp"
#include "field/point.hpp"
#include "field/segment.hpp"
#include "field/triangle.hpp"
#include "geometry/bounds.hpp"

namespace convray::geometry {

using Kind = scene::Implicit::Kind;

namespace {

// POV-Ray's blob counts points within this of the threshold as inside.
constexpr double kBlobInsideTolerance = 1e-6;

size_t component_count(const implicit::ConvolutionObject& o, Kind kind) {
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
                             implicit::SupportCache* cache)
    : surface_(record.object, cache),
      is_blob_(record.is_blob),
      object_surface_(std::move(surface)) {
  if (!record.component_textures.empty()) index_components(record);
}

void ImplicitShape::index_components(const scene::Implicit& record) {
  components_ = record.object;
  // Which listed component has which surface description.
  std::vector<std::vector<const SurfaceInfo*>> surface_of(6);
  for (int k = 0; k < 6; ++k) {
    surface_of[size_t(k)].assign(component_count(components_, Kind(k)), object_surface_.get());
  }
  for (const scene::ComponentTexture& given : record.component_textures) {
    if (given.index >= record.component_order.size()) {
      throw std::invalid_argument("component texture for component " + std::to_string(given.index) +
                                  ", which does not exist");
    }
    const auto [kind, index] = record.component_order[given.index];
    if (index >= component_count(components_, kind)) {
      throw std::invalid_argument("component order names a missing component");
    }
    auto info = std::make_shared<SurfaceInfo>(*object_surface_);
    if (given.texture) info->texture = given.texture;
    component_surfaces_.push_back(info);
    surface_of[size_t(kind)][index] = info.get();
  }
  for (int k = 0; k < 6; ++k) {
    for (size_t i = 0; i < surface_of[size_t(k)].size(); ++i) {
      textured_lookup_.push_back({Kind(k), i, surface_of[size_t(k)][i]});
    }
  }
  for (const implicit::MeshComponent& mesh : components_.meshes) {
    Box3 box;
    for (const field::Triangle& t : mesh.triangles) {
      box.extend(t.a);
      box.extend(t.b);
      box.extend(t.c);
    }
    if (!is_empty(box)) {
      box.lo -= mesh.weight.radius;
      box.hi += mesh.weight.radius;
    }
    mesh_reach_.push_back(box);
  }
}

double ImplicitShape::contribution(const Component& c, const Vec3& p) const {
  const implicit::ConvolutionObject& o = components_;
  switch (c.kind) {
    case Kind::mesh: {
      const implicit::MeshComponent& mesh = o.meshes[c.index];
      if (!contains(mesh_reach_[c.index], p)) return 0.0;
      double sum = 0.0;
      for (const field::Triangle& t : mesh.triangles) {
        sum += field::triangle_value(p, t, mesh.weight.radius);
      }
      return mesh.weight.strength * sum;
    }
    case Kind::segment: {
      const auto& s = o.segments[c.index];
      return s.weight.strength * field::segment_value(p, s.segment, s.weight.radius);
    }
    case Kind::arc: {
      const auto& a = o.arcs[c.index];
      return a.weight.strength * field::arc_value(p, a.arc, a.weight.radius);
    }
    case Kind::point: {
      const auto& q = o.points[c.index];
      return q.weight.strength * field::point_value(p, q.center, q.weight.radius);
    }
    case Kind::blob_sphere: {
      const auto& b = o.blob_spheres[c.index];
      return field::blob_sphere_field(p, b.center, b.weight.radius, b.weight.strength).value;
    }
    case Kind::blob_cylinder: {
      const auto& b = o.blob_cylinders[c.index];
      return field::blob_cylinder_field(p, b.base, b.apex, b.weight.radius, b.weight.strength)
          .value;
    }
  }
  return 0.0;
}

const SurfaceInfo* ImplicitShape::surface_at(const Vec3& p) const {
  if (textured_lookup_.empty()) return object_surface_.get();
  const SurfaceInfo* dominant = object_surface_.get();
  double largest = 0.0;
  for (const Component& c : textured_lookup_) {
    const double value = contribution(c, p);
    if (value > largest) {
      largest = value;
      dominant = c.surface;
    }
  }
  return dominant;
}

Box3 ImplicitShape::bounds() const { return surface_.bounds(); }

void ImplicitShape::crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                              TraceStats& stats) const {
  // Roots are searched where the field can be non-zero; the support box is wider than the
  // surface, so no crossing sits on its faces.
  double t0 = tmin, t1 = tmax;
  if (!clip_to_box(ray, surface_.bounds(), t0, t1)) return;
  thread_local std::vector<double> roots;  // not re-entered: roots() calls no shape
  roots.clear();
  surface_.roots(ray, t0, t1, roots, stats);
  for (const double t : roots) {
    if (!(t > tmin && t < tmax)) continue;
    const implicit::SurfaceHit hit = implicit::make_surface_hit(surface_, ray, t);
    out.push_back({t, hit.normal, surface_at(hit.point)});
  }
}

std::optional<Crossing> ImplicitShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                      TraceStats& stats) const {
  double t0 = tmin, t1 = tmax;
  if (!clip_to_box(ray, surface_.bounds(), t0, t1)) return std::nullopt;
  const auto hit = surface_.first_hit(ray, t0, t1, stats);
  if (!hit) return std::nullopt;
  if (hit->t > tmin && hit->t < tmax) return Crossing{hit->t, hit->normal, surface_at(hit->point)};
  // A root on an end of the closed interval the surface searched: the open one wants the next.
  std::vector<Crossing> all;
  crossings(ray, tmin, tmax, all, stats);
  if (all.empty()) return std::nullopt;
  return all.front();
}

bool ImplicitShape::inside(const Vec3& p) const {
  const double value = surface_.field(p).value;
  const double threshold = surface_.threshold();
  return is_blob_ ? value > threshold - kBlobInsideTolerance : value >= threshold;
}

}  // namespace convray::geometry
