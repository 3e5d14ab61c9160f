#pragma once
// POV-Ray's `plane { normal, distance }`: the points p with p . n < distance (n the unit
// normal) are inside; the surface has no bounds.
#include "geometry/primitive.hpp"

namespace convray::geometry {

class PlaneShape final : public Shape {
 public:
  // `normal` need not be unit; `distance` is measured along the unit normal.
  PlaneShape(const Vec3& normal, double distance, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

 private:
  Vec3 normal_;  // unit
  double distance_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
