#pragma once
// The scene's objects made ready for rays: one Shape per top-level object (classic
// primitives, CSG, blobs and convolution objects), built once from the immutable Scene.
#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.hpp"
#include "scene/scene.hpp"

namespace convray::geometry {

// Builds the traceable form of one object record (and its children). Throws InputError at
// the object's source location for what cannot be built (a degenerate shape, say).
ShapePtr build_shape(const scene::Object& object);

class World {
 public:
  explicit World(const scene::Scene& scene);
  ~World();
  World(World&&) noexcept;

  // The union of the finite objects' bounds (empty if there are none).
  Box3 bounds() const;

  // The nearest crossing of any object in (tmin, tmax).
  std::optional<Crossing> first_hit(const Ray& ray, double tmin, double tmax,
                                    TraceStats& stats) const;
  // Every crossing in (tmin, tmax) of the objects that cast shadows, ascending: a shadow ray
  // is dimmed by each transparent surface it passes and stopped by the first opaque one.
  void shadow_crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                        TraceStats& stats) const;
  // Whether p is inside any object (for rays that start inside a refracting solid).
  bool inside_any(const Vec3& p) const;

 private:
  std::vector<ShapePtr> shapes_;
  std::vector<Box3> bounds_;
};

}  // namespace convray::geometry
