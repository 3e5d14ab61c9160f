#pragma once
// POV-Ray's `blob` and our `convolution` object, of either kernel: the surface F = T of an
// implicit::Surface (made by implicit::make_surface) in the object's own space. Crossings are
// the surface's hits (each refined on the exact field), normals -grad F / |grad F| (or a
// truncation box's face, kernel cauchy). Inside is F >= T; for a blob POV-Ray's F > T - 1e-6.
//
// Per-component textures: POV-Ray blends the textures of the components by their share of
// the field at the point. We simplify to the dominant one: a crossing takes the surface
// description of the component contributing most to the field there (components without a
// texture of their own count as the object's). Only the primitives whose support holds the
// point are asked (the support index's point query), so a mesh component of 100,000
// triangles costs what its few nearby triangles cost.
#include <memory>
#include <vector>

#include "geometry/primitive.hpp"
#include "implicit/surface.hpp"
#include "scene/object.hpp"

namespace convray::geometry {

class ImplicitShape final : public Shape {
 public:
  // Throws std::invalid_argument for what the kernel's surface refuses (a radius that is not
  // positive, a threshold that is not positive, arcs under kernel cauchy) and for component
  // textures that name no component. `cache` and `tracer` are make_surface's.
  ImplicitShape(const scene::Implicit& record, SurfaceInfoPtr surface,
                implicit::SupportCache* cache = nullptr,
                implicit::Tracer tracer = implicit::Tracer::fast);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  bool blocks_light() const override { return blocks_light_; }
  // The surface's any-hit query (implicit::Surface::occluded): no root refined, no normal.
  bool any_crossing(const Ray& ray, double tmin, double tmax, TraceStats& stats) const override;

  const implicit::Surface& surface() const { return *surface_; }
  // The surface description a crossing at p takes (the dominant component's).
  const SurfaceInfo* surface_at(const Vec3& p) const;

 private:
  void index_components(const scene::Implicit& record);

  std::unique_ptr<const implicit::Surface> surface_;
  bool is_blob_;
  SurfaceInfoPtr object_surface_;
  // Only when some component has its own texture: each component's surface description, by
  // kind and index (the object's where the component has none), and the descriptions made.
  std::vector<std::vector<const SurfaceInfo*>> surface_of_;
  std::vector<SurfaceInfoPtr> component_surfaces_;
  bool blocks_light_ = false;  // every surface description casts shadows and is opaque
};

}  // namespace convray::geometry
