#pragma once
// POV-Ray's `sphere { center, radius }`.
#include "geometry/primitive.hpp"

namespace convray::geometry {

class SphereShape final : public Shape {
 public:
  SphereShape(const Vec3& center, double radius, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

 private:
  Vec3 center_;
  double radius_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
