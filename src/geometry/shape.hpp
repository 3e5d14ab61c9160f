#pragma once
// What the tracer asks of every object, classic primitive, CSG or implicit surface alike: every
// crossing of its boundary along a ray (CSG combines these), the first one, and whether a
// point is inside (CSG and the inside tests of `inverse`, `clipped_by`, refraction).
#include <memory>
#include <optional>
#include <vector>

#include "core/ray.hpp"
#include "core/trace_stats.hpp"
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::geometry {

// What the renderer needs to shade a surface: resolved at build time (a CSG child without a
// texture gets its parent's, an object without any gets the default texture), owned by the
// shape tree, shared by every crossing of that surface.
struct SurfaceInfo {
  scene::TexturePtr texture;        // never null after building
  scene::TexturePtr interior_texture;  // seen from inside the solid; null: `texture`
  scene::Interior interior;
  bool no_shadow = false;
  bool no_image = false;       // hidden from camera rays and their transmitted rays
  bool no_reflection = false;  // hidden from reflected rays (and what they pass through)
  bool double_illuminate = false;  // lights behind the surface light its far side
  bool hollow = false;             // fog is drawn inside the solid
};

struct Crossing {
  double t = 0.0;                   // along the ray (unit direction: a distance)
  Vec3 normal{0.0, 0.0, 1.0};       // unit, world space, pointing out of the solid
  const SurfaceInfo* surface = nullptr;
  // Set by an instance (geometry/instance.hpp): the surface's textures are in the space this
  // transform places in the world, and are evaluated at the hit point carried back there.
  // Null: the textures are where the surface is.
  const scene::Transform* texture_space = nullptr;
};

class Shape {
 public:
  virtual ~Shape() = default;

  // World-space bounds; infinite components for unbounded shapes (plane, inverse, ...).
  virtual Box3 bounds() const = 0;

  // Appends every crossing in (tmin, tmax), ascending in t. `ray.direction` has unit length.
  virtual void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                         TraceStats& stats) const = 0;

  // The first crossing in (tmin, tmax). The default takes the first of crossings(); shapes
  // that can stop early override it.
  virtual std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                                 TraceStats& stats) const;

  // Whether p is inside the solid (on the boundary: either answer).
  virtual bool inside(const Vec3& p) const = 0;

  // Whether every crossing of this shape stops a shadow ray outright (each of its surfaces
  // casts shadows with a texture opaque everywhere), so that any_crossing() settles a shadow
  // ray. Shapes whose crossings cost much to refine say so (implicit surfaces); for the rest
  // the shadow ray follows first_crossing() as for transparent surfaces.
  virtual bool blocks_light() const { return false; }
  // Whether some crossing lies in (tmin, tmax), found without refining where it is or its
  // normal where the shape can (shadow rays). The default asks first_crossing().
  virtual bool any_crossing(const Ray& ray, double tmin, double tmax, TraceStats& stats) const {
    return first_crossing(ray, tmin, tmax, stats).has_value();
  }

  // World-space bounds of the points where inside() can be true (CSG and clipped_by bound
  // what they keep with them): bounds() for closed solids, infinite for half-spaces (plane,
  // disc) and inverted shapes, empty for open surfaces that have no inside.
  virtual Box3 inside_bounds() const { return bounds(); }
};

using ShapePtr = std::unique_ptr<Shape>;

}  // namespace convray::geometry
