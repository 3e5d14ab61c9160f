#pragma once
// The object modifiers that change what a shape is, not where: `inverse` (inside and outside
// swapped, normals flipped), `clipped_by` (only the surface inside every clipping object is
// kept, without capping the cut, as POV-Ray) and `bounded_by` (rays that miss the bound skip
// the object; a bound that holds the object changes nothing).
#include <vector>

#include "geometry/shape.hpp"

namespace convray::geometry {

class InvertedShape final : public Shape {
 public:
  explicit InvertedShape(ShapePtr child);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

 private:
  ShapePtr child_;
};

class ClippedShape final : public Shape {
 public:
  ClippedShape(ShapePtr shape, std::vector<ShapePtr> clips);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

 private:
  bool inside_clips(const Vec3& p) const;

  ShapePtr shape_;
  std::vector<ShapePtr> clips_;
  Box3 bounds_, inside_bounds_;
};

class BoundedShape final : public Shape {
 public:
  BoundedShape(ShapePtr shape, const Shape& bound);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

 private:
  ShapePtr shape_;
  Box3 region_;  // the box around the bounding object
  Box3 bounds_;
};

}  // namespace convray::geometry
