#pragma once
// POV-Ray's text object (scene::Text): glyph outlines of quadratic Bezier pieces, extruded
// from z = 0 to z = thickness. Along a ray the crossings are exact: the two caps where the
// outline winds around the ray's point in the cap's plane, and each side piece where the
// quadratic of the piece meets the ray's trace in the xy plane.
#include <vector>

#include "geometry/primitive.hpp"
#include "scene/object.hpp"

namespace convray::geometry {

// Winding number of the closed contours made of `pieces` around `p` (nonzero: inside). A
// horizontal ray towards +x counts the pieces it crosses, each piece taken over s in [0, 1)
// so that a shared end is counted once.
int outline_winding(const std::vector<scene::OutlinePiece>& pieces, const Vec2& p);

class TextShape final : public Shape {
 public:
  TextShape(const scene::Text& text, SurfaceInfoPtr surface);

  Box3 bounds() const override { return bounds_; }
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;

 private:
  struct Glyph {
    std::vector<scene::OutlinePiece> pieces;
    Box3 box;  // of the control points (the curves stay in their hull), z from 0 to thickness
  };
  void side_crossings(const Glyph& glyph, const Ray& ray, double enter, double leave,
                      std::vector<Crossing>& out) const;

  std::vector<Glyph> glyphs_;
  double thickness_;
  Box3 bounds_;
  SurfaceInfoPtr surface_;
};

}  // namespace convray::geometry
