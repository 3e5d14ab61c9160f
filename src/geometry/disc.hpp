#pragma once
// POV-Ray's `disc { center, normal, radius [, hole_radius] }`: an infinitely thin annulus.
// Like POV-Ray, its inside is the half-space behind the normal.
#include "geometry/primitive.hpp"

namespace convray::geometry {

class DiscShape final : public Shape {
 public:
  DiscShape(const Vec3& center, const Vec3& normal, double radius, double hole_radius,
            SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

 private:
  Vec3 center_, normal_;  // unit normal
  double radius_, hole_radius_;
  SurfaceInfoPtr surface_;
};

// Bounds of the disc of `radius` about `center` perpendicular to the unit vector `normal`:
// along axis i it reaches radius * sqrt(1 - normal_i^2).
Box3 disc_bounds(const Vec3& center, const Vec3& normal, double radius);

}  // namespace convray::geometry
