#pragma once
// A convolution object under the Cauchy kernel of McCormack and Sherstyuk made ready for
// queries: its field at any point and its surface F = T along rays. The kernel has infinite
// support, so each primitive's field is truncated to its own bounding box grown by the
// component's radius (the truncation margin): zero outside, the closed form inside. The sum is
// therefore discontinuous on the boxes' faces, and so is the surface: that is the behaviour
// the paper's Fig. 6 and Fig. 9 show, and it is reproduced, not hidden.
//
// Along a ray the field is smooth between consecutive box entries and exits. On each such
// piece F - T is marched with steps its Lipschitz bound makes safe (the sum over the active
// primitives of strength x the bound on their gradient), sign changes are refined on the
// exact field, and a sign change of F - T across a box face is a crossing too (on the face).
// Both kernels answer through the Surface interface (surface.hpp); the quartic kernel's
// ConvolutionSurface shares none of this march.
#include <cstdint>
#include <optional>
#include <vector>

#include "field/sample.hpp"
#include "implicit/box_bvh.hpp"
#include "scene/convolution_object.hpp"
#include "implicit/surface.hpp"
#include "core/ray.hpp"
#include "core/trace_stats.hpp"

namespace convray::implicit {

// One skeleton primitive under the Cauchy kernel.
struct CauchyPrimitive {
  enum class Shape : uint8_t { point, segment, triangle };
  Shape shape = Shape::point;
  Vec3 v[3]{};  // point: v[0]; segment: v[0], v[1]; triangle: all three
  double strength = 1.0;
  // |strength| x area (length, 1): |grad (strength x field)| <= this x max |h'| beyond the
  // distance to the primitive; for triangles never more than slope_cap (a whole plane's).
  double weighted_measure = 0.0;
  double slope_cap = 0.0;
  Box3 extent;             // the primitive's own bounding box (not grown)
  scene::ComponentRef component;  // the component it belongs to (a mesh's triangles: the mesh)
};

class CauchySurface final : public Surface {
 public:
  // Throws std::invalid_argument for an object the Cauchy kernel cannot describe: arcs or
  // blob components (no closed form here), a sharpness, radius or threshold that is not
  // positive and finite.
  explicit CauchySurface(const scene::ConvolutionObject& object);

  double threshold() const override { return threshold_; }
  double sharpness() const { return s_; }
  // The union of the truncation boxes: F = 0 outside.
  Box3 bounds() const override { return bvh_.bounds(); }
  size_t primitive_count() const override { return primitives_.size(); }
  // Triangles left out as exact repeats of another of their mesh, summed once with their
  // multiplicity (repeated_triangles.hpp).
  size_t merged_triangle_count() const { return merged_triangles_; }
  size_t memory_bytes() const override;
  const std::vector<CauchyPrimitive>& primitives() const { return primitives_; }
  // The truncation boxes in object space: primitive i's field is zero outside box i.
  std::vector<Box3> support_boxes() const override { return bvh_.boxes(); }

  // strength x the untruncated closed-form field of primitive i at p.
  field::FieldSample primitive_field(size_t i, const Vec3& p) const;
  double primitive_value(size_t i, const Vec3& p) const;
  // The truncated field: the sum over the primitives whose (closed) box holds p.
  field::FieldSample field(const Vec3& p) const override;

  // Each contributing primitive's weighted field at p, by component (for component textures).
  void component_values(const Vec3& p, std::vector<ComponentValue>& out) const override;

  // Every crossing in [tmin, tmax], ascending: smooth ones refined on the exact field (normal
  // -grad F / |grad F|), and sign changes across box faces (normal: the face's, pointing out
  // of the solid F >= T).
  void hits(const Ray& ray, double tmin, double tmax, std::vector<SurfaceHit>& out,
            TraceStats& stats) const override;
  void roots(const Ray& ray, double tmin, double tmax, std::vector<double>& out,
             TraceStats& stats) const override;
  std::optional<SurfaceHit> first_hit(const Ray& ray, double tmin, double tmax,
                                      TraceStats& stats) const override;
  bool occluded(const Ray& ray, double tmin, double tmax, TraceStats& stats) const override;

  // The smallest step the march takes (where F - T is within step x Lipschitz of zero): two
  // crossings closer than this along a ray may be missed.
  double min_step() const { return min_step_; }

 private:
  struct Tracer;  // one piece of a ray at a time: march, refine, report (cauchy_surface.cpp)
  // Sweeps the ray's box entries and exits in [tmin, tmax], calling visit(SurfaceHit) for
  // each crossing in order until it returns false.
  template <class Visit>
  void trace(const Ray& ray, double tmin, double tmax, TraceStats& stats, bool want_normals,
             Visit&& visit) const;

  double s_ = 1.0;
  double threshold_ = 1.0;
  double min_step_ = 1e-5;
  std::vector<CauchyPrimitive> primitives_;
  size_t merged_triangles_ = 0;
  BoxBvh bvh_;
};

// The slow exact twin of CauchySurface's tracer: samples the truncated field every `step`
// along the ray, asking every primitive (box test, no hierarchy, no pieces), and bisects each
// sign change of F - T to rounding level (a jump across a box face bisects to the face).
void cauchy_reference_roots(const CauchySurface& surface, const Ray& ray, double tmin, double tmax,
                            double step, std::vector<double>& out);
// The truncated field by brute force: every primitive's box tested.
double cauchy_brute_force_value(const CauchySurface& surface, const Vec3& p);

}  // namespace convray::implicit
