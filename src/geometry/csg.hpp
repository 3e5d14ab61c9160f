#pragma once
// POV-Ray's constructive solid geometry on the crossings of the children (DESIGN.md 5):
//  - union: every child's crossings (internal surfaces stay); inside any child;
//  - merge: a child's crossings outside every other child; inside any child;
//  - intersection: a child's crossings inside every other child; inside all;
//  - difference: the first child's crossings outside the rest, and the others' crossings
//    inside the first and outside the rest, their normals flipped; inside the first and
//    none of the rest.
// Each kept crossing keeps its child's surface description (texture, interior).
#include <vector>

#include "geometry/primitive.hpp"
#include "scene/object.hpp"

namespace convray::geometry {

class CsgShape final : public Shape {
 public:
  CsgShape(scene::CsgOperation operation, std::vector<ShapePtr> children);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

 private:
  // Whether a crossing of child `from` at p survives, and whether its normal flips.
  bool keeps(size_t from, const Vec3& p) const;
  // Whether the ray meets the bounds within [tmin, tmax].
  bool meets(const Ray& ray, double tmin, double tmax) const;
  // Children's crossings, merged in ascending order, as (crossing, child).
  void child_crossings(const Ray& ray, double tmin, double tmax,
                       std::vector<std::pair<Crossing, size_t>>& out, TraceStats& stats) const;

  scene::CsgOperation operation_;
  std::vector<ShapePtr> children_;
  std::vector<Box3> child_bounds_;  // each child's bounds(), cached
  Box3 bounds_, inside_bounds_;
};

}  // namespace convray::geometry
