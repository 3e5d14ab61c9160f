#pragma once
// POV-Ray's `cone` and `cylinder` (a cone whose radii are equal): the solid swept by a disc
// whose radius goes linearly from base_radius at `base` to cap_radius at `cap`, with flat end
// caps unless `open`. Like POV-Ray, an open one keeps the solid's inside (the caps are only
// not drawn). Either radius may be 0 (a pointed cone), not both.
#include "geometry/primitive.hpp"

namespace convray::geometry {

class ConeShape final : public Shape {
 public:
  ConeShape(const Vec3& base, double base_radius, const Vec3& cap, double cap_radius, bool open,
            SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

 private:
  double radius_at(double height) const { return base_radius_ + slope_ * height; }
  void side_crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out) const;
  void cap_crossing(const Ray& ray, double height, double radius, double tmin, double tmax,
                    std::vector<Crossing>& out) const;

  Vec3 base_, cap_, axis_;  // axis: unit, base -> cap
  double length_;
  double base_radius_, cap_radius_;
  double slope_;  // radius change per unit of height
  bool open_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
