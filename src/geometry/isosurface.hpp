#pragma once
// POV-Ray's `isosurface { function { f } contained_by { box | sphere } threshold T
// max_gradient G accuracy A open }`: within the container, inside where f < T; the surface is
// f = T, and, unless `open`, the container's own surface where f < T there.
//
// Along a ray, g(t) = f(ray.at(t)) - T changes by at most G per unit of t (G is the scene's
// promise, as in POV-Ray: too small a G can step over thin parts). From a point where
// |g| = v no root lies closer than v / G, so the march steps by max(v / G, A) and every sign
// change is refined by the tracers' bracketed refiner (core/bracket_refine.hpp).
//
// The crossing is then reported where POV-Ray 3.7 reports it, which is what `accuracy`
// means there: POV-Ray halves the ray's stretch inside the container until a piece is no
// longer than A and reports the far end of the piece that holds the root, with the forward
// difference of f, step A, as its normal (measured on the povray binary: trace() on
// x^3 + y^2 + z^4 = 1 at two accuracies, from outside and inside, box and sphere containers;
// the points agree to the last digit printed). Scenes that place objects with trace() on an
// isosurface (isocacti, trace2) then place them where POV-Ray does.
#include <memory>

#include "geometry/primitive.hpp"
#include "scene/object.hpp"

namespace convray::geometry {

class IsosurfaceShape final : public Shape {
 public:
  IsosurfaceShape(const scene::Isosurface& iso, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

  double value(const Vec3& p) const { return (*iso_.function)(p.x, p.y, p.z) - iso_.threshold; }
  // f's forward difference with step `accuracy` at p, normalized (POV-Ray's normal).
  Vec3 outward_normal(const Vec3& p) const;
  // Where POV-Ray reports the root at `root` of the stretch [from, to] inside the container:
  // the far end of the piece holding it, after halving [from, to] to `accuracy` or less.
  double povray_crossing(double root, double from, double to) const;

 private:
  bool in_container(const Vec3& p) const;
  bool clip_to_container(const Ray& ray, double& enter, double& leave) const;
  Vec3 container_normal(const Vec3& p) const;
  // The crossings in (tmin, tmax), ascending; stops after the first when `first_only`.
  void march(const Ray& ray, double tmin, double tmax, bool first_only,
             std::vector<Crossing>& out) const;

  scene::Isosurface iso_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
