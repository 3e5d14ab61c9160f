#pragma once
// POV-Ray's `polygon`: flat sub-polygons in one plane, a point being inside when it lies
// inside an odd number of them (so a sub-polygon within another cuts a hole). Infinitely
// thin, like disc; it has no inside (POV-Ray's polygon is not solid).
#include <vector>

#include "geometry/primitive.hpp"

namespace convray::geometry {

class PolygonShape final : public Shape {
 public:
  // `outlines`: each sub-polygon's corners, in order, all in one plane with `normal`.
  PolygonShape(std::vector<std::vector<Vec3>> outlines, const Vec3& normal,
               SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

  // Whether a point of the polygon's plane lies inside an odd number of the outlines.
  bool covers(const Vec3& point_in_plane) const;

 private:
  std::vector<std::vector<Vec2>> outlines_;  // projected onto the two axes `u_`, `v_`
  Vec3 normal_;                              // unit
  double offset_;                            // the plane: dot(normal, p) = offset
  int u_, v_;                                // the axes kept by the projection
  Box3 bounds_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
