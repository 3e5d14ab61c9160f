#pragma once
// A convolution object with `kernel cauchy`: the surface F = T of a CauchySurface (the
// McCormack-Sherstyuk kernel, truncated per primitive to its box) in the object's own space.
// Crossings come with the exact gradient's normal, or a box face's where the truncation makes
// F - T jump across it; inside is F >= T. Component textures work as for ImplicitShape: a
// crossing takes the texture of the component contributing most to the field there.
#include <vector>

#include "geometry/primitive.hpp"
#include "implicit/cauchy_surface.hpp"
#include "scene/object.hpp"

namespace convray::geometry {

class CauchyShape final : public Shape {
 public:
  // Throws std::invalid_argument for what CauchySurface refuses and for component textures
  // that name no component.
  CauchyShape(const scene::Implicit& record, SurfaceInfoPtr surface);

  Box3 bounds() const override { return surface_.bounds(); }
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

  const implicit::CauchySurface& surface() const { return surface_; }
  const SurfaceInfo* surface_at(const Vec3& p) const;

 private:
  implicit::CauchySurface surface_;
  SurfaceInfoPtr object_surface_;
  // Only when some component has its own texture: (component, its surface description).
  std::vector<std::pair<implicit::ComponentRef, SurfaceInfoPtr>> component_surfaces_;
};

}  // namespace convray::geometry
