#pragma once
// A convolution object under the paper's quartic kernel made ready for queries (the Surface
// interface of surface.hpp, made by make_surface): its field at any point (through the
// acceleration structure's point query) and its surface F = T along rays, found by the
// paper's per-interval degree-6 fits and Bézier clipping (or, where only spheres reach, the
// exact quartic of sphere_sweep.hpp), every root polished on the exact field.
// reference_tracer.hpp is the slow exact twin tests compare this with.
#include <memory>
#include <optional>
#include <vector>

#include "implicit/surface.hpp"

namespace convray::implicit {

class ConvolutionSurface final : public Surface {
 public:
  // With a cache, mesh components that carry a MeshSource take the hierarchy over their
  // supports from it (built there once, then shared); the answers are the same either way.
  explicit ConvolutionSurface(const scene::ConvolutionObject& object, SupportCache* cache = nullptr,
                              Tracer tracer = Tracer::fast);
  ~ConvolutionSurface() override;
  ConvolutionSurface(ConvolutionSurface&&) noexcept;
  ConvolutionSurface& operator=(ConvolutionSurface&&) noexcept;

  double threshold() const override;
  // Union of the primitives' supports (primitive grown by its radius): F = 0 outside.
  Box3 bounds() const override;
  size_t primitive_count() const override;
  // Mesh triangles left out as exact repeats: each distinct triangle is summed once with its
  // multiplicity (repeated_triangles.hpp).
  size_t merged_triangle_count() const;
  // Bytes held by the primitives and the acceleration structure.
  size_t memory_bytes() const override;
  // One per distinct triangle of each mesh (exact repeats share one), segment, arc, point and
  // blob component.
  std::vector<Box3> support_boxes() const override;

  // The exact field and gradient at p (sum over the primitives whose support holds p).
  field::FieldSample field(const Vec3& p) const override;

  // The weighted field at p of each primitive whose support holds p (surface.hpp).
  void component_values(const Vec3& p, std::vector<ComponentValue>& out) const override;

  Tracer tracer() const;

  // Every t in [tmin, tmax] where F(ray.at(t)) = T, ascending, each polished on the exact field.
  void roots(const Ray& ray, double tmin, double tmax, std::vector<double>& out,
             TraceStats& stats) const override;
  // The roots with the normals of the exact gradient (make_surface_hit).
  void hits(const Ray& ray, double tmin, double tmax, std::vector<SurfaceHit>& out,
            TraceStats& stats) const override;
  // The first crossing in [tmin, tmax], with the normal from the exact gradient.
  std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                      TraceStats& stats) const override;
  // Whether any crossing lies in [tmin, tmax] (shadow rays).
  bool occluded(const Ray& ray, double tmin, double tmax, TraceStats& stats) const override;

  struct Impl;  // primitives, acceleration structure, tracer state (convolution_surface.cpp)
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace convray::implicit
