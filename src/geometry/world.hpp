#pragma once
// The scene's objects made ready for rays: one Shape per top-level object (classic
// primitives, CSG, blobs and convolution objects), or per member of a union that splits,
// built once from the immutable Scene.
#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.hpp"
#include "implicit/tracer.hpp"
#include "scene/scene.hpp"

namespace convray::implicit {
class SupportCache;
}

namespace convray::geometry {

class SharedUnions;

// Builds the traceable form of one object record (and its children). Throws InputError at
// the object's source location for what cannot be built (a degenerate shape, say).
// Conventions: CSG children, clipped_by and bounded_by objects are in the object's own space
// (its transform moves them with it); a child without texture or interior takes its
// parent's, an object without any gets scene::default_texture() and Interior{}.
// Convolution objects take their meshes' hierarchies from `cache` when given one (animations,
// implicit/support_cache.hpp); the shapes answer the same either way. `tracer` picks how
// convolution surfaces are traced: the fast path, or its exact reference twin.
ShapePtr build_shape(const scene::Object& object, implicit::SupportCache* cache = nullptr,
                     implicit::Tracer tracer = implicit::Tracer::fast);

// The shapes of one object for the scene's hierarchy: build_shape's, except that a union
// POV-Ray would split (split_union, its default) gives its members, each placed, textured and
// flagged as inside the union (recursively), so that rays find them as fast as objects that
// stand alone. A placement of a declared union (scene/instance.hpp) gives one TransformedShape
// over the union's members, built once in `shared` (geometry/instance.hpp); without `shared`
// it is split as its copy. Appends to `out`.
void build_split_shapes(const scene::Object& object, std::vector<ShapePtr>& out,
                        implicit::SupportCache* cache = nullptr,
                        implicit::Tracer tracer = implicit::Tracer::fast,
                        SharedUnions* shared = nullptr);

class World {
 public:
  // Objects are built one after the other; `cache` (optional) and `tracer` are handed to each.
  explicit World(const scene::Scene& scene, implicit::SupportCache* cache = nullptr,
                 implicit::Tracer tracer = implicit::Tracer::fast);
  ~World();
  World(World&&) noexcept;

  // The union of the finite objects' bounds (empty if there are none).
  Box3 bounds() const;

  // Which objects a search asks: shadow rays settle the objects that block light outright
  // (Shape::blocks_light) with blocked() and follow the others crossing by crossing.
  enum class Objects { all, letting_light_through };

  // Who looks along a ray: camera rays (and the rays they send on through transparent
  // surfaces) do not see no_image surfaces, reflected rays (and theirs) no_reflection ones;
  // shadow rays and the rest see every surface.
  enum class Viewer { any, camera, reflection };

  // The nearest crossing in (tmin, tmax) of any object, of the surfaces `viewer` sees.
  std::optional<Crossing> first_hit(const Ray& ray, double tmin, double tmax, TraceStats& stats,
                                    Objects objects = Objects::all,
                                    Viewer viewer = Viewer::any) const;
  // Whether an object that blocks light outright crosses the ray in (tmin, tmax): an any-hit
  // query, no root refined.
  bool blocked(const Ray& ray, double tmin, double tmax, TraceStats& stats) const;
  // Every crossing in (tmin, tmax) of the objects that cast shadows, ascending: a shadow ray
  // is dimmed by each transparent surface it passes and stopped by the first opaque one.
  void shadow_crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                        TraceStats& stats) const;
  // Whether p is inside any object (for rays that start inside a refracting solid).
  bool inside_any(const Vec3& p) const;
  // Whether p is inside an object that is not hollow: POV-Ray draws no fog there.
  bool inside_solid(const Vec3& p) const;
  // Whether some object is not hollow (else inside_solid is always false).
  bool has_solids() const { return solids_ > 0; }

  // The slow exact twins of first_hit and shadow_crossings: every object asked, no
  // hierarchy (tests compare them).
  std::optional<Crossing> first_hit_brute_force(const Ray& ray, double tmin, double tmax,
                                                TraceStats& stats) const;
  bool blocked_brute_force(const Ray& ray, double tmin, double tmax, TraceStats& stats) const;
  void shadow_crossings_brute_force(const Ray& ray, double tmin, double tmax,
                                    std::vector<Crossing>& out, TraceStats& stats) const;
  // The shapes built: one per object, a split union's members counted one by one.
  size_t object_count() const { return shapes_.size(); }
  // The i-th shape built (i < object_count()), in the scene's order.
  const Shape& shape(size_t i) const { return *shapes_[i]; }
  // The declared unions whose placements share one hierarchy (geometry/instance.hpp), and
  // their members, each union's counted once however often it is placed.
  size_t shared_union_count() const { return shared_unions_; }
  size_t shared_member_count() const { return shared_members_; }

 private:
  struct Index;  // a BVH over the bounded objects' boxes, and the list of unbounded ones

  std::vector<ShapePtr> shapes_;
  std::vector<uint8_t> blocks_light_;  // shapes_[i]->blocks_light(), asked once
  size_t blockers_ = 0;                // how many do
  std::vector<uint8_t> hollow_;        // built from a hollow object
  size_t solids_ = 0;                  // how many are not
  size_t shared_unions_ = 0, shared_members_ = 0;
  std::vector<Box3> bounds_;
  std::unique_ptr<const Index> index_;
};

}  // namespace convray::geometry
