#pragma once
// A convolution object made ready for queries: its field at any point (through the
// acceleration structure's point query) and its surface F = T along rays, found by the
// paper's per-interval degree-6 fits and Bézier clipping (or, where only spheres reach, the
// exact quartic of sphere_sweep.hpp), every root polished on the exact field.
// reference_tracer.hpp is the slow exact twin tests compare this with.
#include <memory>
#include <optional>
#include <vector>

#include "field/sample.hpp"
#include "implicit/convolution_object.hpp"
#include "implicit/ray.hpp"
#include "implicit/trace_stats.hpp"
#include "implicit/tracer.hpp"

namespace convray::implicit {

class SupportCache;

class ConvolutionSurface {
 public:
  // With a cache, mesh components that carry a MeshSource take the hierarchy over their
  // supports from it (built there once, then shared); the answers are the same either way.
  explicit ConvolutionSurface(const ConvolutionObject& object, SupportCache* cache = nullptr,
                              Tracer tracer = Tracer::fast);
  ~ConvolutionSurface();
  ConvolutionSurface(ConvolutionSurface&&) noexcept;
  ConvolutionSurface& operator=(ConvolutionSurface&&) noexcept;

  double threshold() const;
  // Union of the primitives' supports (primitive grown by its radius): F = 0 outside.
  Box3 bounds() const;
  size_t primitive_count() const;
  // Mesh triangles left out as exact repeats: each distinct triangle is summed once with its
  // multiplicity (repeated_triangles.hpp).
  size_t merged_triangle_count() const;
  // Bytes held by the primitives and the acceleration structure.
  size_t memory_bytes() const;

  // The exact field and gradient at p (sum over the primitives whose support holds p).
  field::FieldSample field(const Vec3& p) const;

  // The weighted field at p of each primitive whose support holds p, named by the component
  // it belongs to (a mesh's triangles each under their mesh), appended to `out`: what a
  // per-component texture needs to know which component dominates at p.
  struct ComponentValue {
    ComponentRef component;
    double value = 0.0;
  };
  void component_values(const Vec3& p, std::vector<ComponentValue>& out) const;

  Tracer tracer() const;

  // Every t in [tmin, tmax] where F(ray.at(t)) = T, ascending, each polished on the exact field.
  void roots(const Ray& ray, double tmin, double tmax, std::vector<double>& out,
             TraceStats& stats) const;
  // The first crossing in [tmin, tmax], with the normal from the exact gradient.
  std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                      TraceStats& stats) const;
  // Whether any crossing lies in [tmin, tmax] (shadow rays).
  bool occluded(const Ray& ray, double tmin, double tmax, TraceStats& stats) const;

  struct Impl;  // primitives, acceleration structure, tracer state (convolution_surface.cpp)
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// The surface hit at distance t: the point and the outward unit normal -grad F / |grad F|.
SurfaceHit make_surface_hit(const ConvolutionSurface& surface, const Ray& ray, double t);
// The same, given the field's gradient at ray.at(t).
SurfaceHit surface_hit_from_gradient(const Ray& ray, double t, const Vec3& gradient);

}  // namespace convray::implicit
