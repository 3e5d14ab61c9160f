#pragma once
// POV-Ray's `box { corner1, corner2 }`: axis-aligned in its own space.
#include "geometry/primitive.hpp"

namespace convray::geometry {

class BoxShape final : public Shape {
 public:
  BoxShape(const Vec3& corner1, const Vec3& corner2, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

 private:
  Vec3 lo_, hi_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
