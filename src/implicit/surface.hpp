#pragma once
// The one interface to the surface F = T of a convolution object, whatever its kernel: the
// field and its gradient at a point, each component's share of the field there, and along a
// ray every root, every crossing with its normal, the first one, and whether there is any.
// make_surface picks the kernel's implementation (ConvolutionSurface for the paper's quartic,
// CauchySurface for McCormack and Sherstyuk's), so no caller branches on the kernel.
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "core/ray.hpp"
#include "core/trace_stats.hpp"
#include "field/sample.hpp"
#include "scene/convolution_object.hpp"
#include "implicit/tracer.hpp"
#include "util/math.hpp"

namespace convray::implicit {

class SupportCache;

// The weighted field at a point of one primitive whose support holds it, named by the
// component it belongs to (a mesh's triangles each under their mesh): what a per-component
// texture needs to know which component dominates there.
struct ComponentValue {
  scene::ComponentRef component;
  double value = 0.0;
};

class Surface {
 public:
  virtual ~Surface() = default;

  virtual double threshold() const = 0;
  // Where F can be non-zero: outside this box F = 0 (< T), so no crossing lies outside it.
  virtual Box3 bounds() const = 0;
  virtual size_t primitive_count() const = 0;
  // Bytes held by the primitives and the acceleration structure.
  virtual size_t memory_bytes() const = 0;
  // The closed box around each primitive's support (where its field can be non-zero): F = 0
  // outside their union. What the polygonizer visits.
  virtual std::vector<Box3> support_boxes() const = 0;

  // The exact field and gradient at p.
  virtual field::FieldSample field(const Vec3& p) const = 0;
  // Each contributing primitive's weighted field at p, appended to `out`.
  virtual void component_values(const Vec3& p, std::vector<ComponentValue>& out) const = 0;

  // Every t in [tmin, tmax] where F - T changes sign along the ray, ascending, each refined
  // on the exact field.
  virtual void roots(const Ray& ray, double tmin, double tmax, std::vector<double>& out,
                     TraceStats& stats) const = 0;
  // The same crossings with their points and outward unit normals (-grad F / |grad F|, or
  // the face's where a truncated kernel makes F jump across a box face).
  virtual void hits(const Ray& ray, double tmin, double tmax, std::vector<SurfaceHit>& out,
                    TraceStats& stats) const = 0;
  // The first crossing in [tmin, tmax].
  virtual std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                              TraceStats& stats) const = 0;
  // Whether any crossing lies in [tmin, tmax] (shadow rays).
  virtual bool occluded(const Ray& ray, double tmin, double tmax, TraceStats& stats) const = 0;

 protected:
  Surface() = default;
  Surface(const Surface&) = default;
  Surface& operator=(const Surface&) = default;
};

// The surface of `object` under its kernel. `cache` (optional) provides the quartic kernel's
// mesh hierarchies (support_cache.hpp); `tracer` picks its fast path or its exact reference
// twin. Throws std::invalid_argument for an object the kernel cannot describe.
std::unique_ptr<const Surface> make_surface(const scene::ConvolutionObject& object,
                                            SupportCache* cache = nullptr,
                                            Tracer tracer = Tracer::fast);

// The surface hit at distance t: the point and the outward unit normal -grad F / |grad F|.
SurfaceHit make_surface_hit(const Surface& surface, const Ray& ray, double t);
// The same, given the field's gradient at ray.at(t).
SurfaceHit surface_hit_from_gradient(const Ray& ray, double t, const Vec3& gradient);

}  // namespace convray::implicit
