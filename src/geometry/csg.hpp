#pragma once
// POV-Ray's constructive solid geometry on the crossings of the children (DESIGN.md 5):
//  - union: every child's crossings (internal surfaces stay); inside any child;
//  - merge: a child's crossings outside every other child; inside any child;
//  - intersection: a child's crossings inside every other child; inside all;
//  - difference: the first child's crossings outside the rest, and the others' crossings
//    inside the first and outside the rest, their normals flipped; inside the first and
//    none of the rest.
// Each kept crossing keeps its child's surface description (texture, interior).
// The children sit in two hierarchies (core/bvh.hpp): one over their surfaces' boxes, which rays
// traverse, and one over their insides' boxes, which inside tests query; so a ray or a point
// costs about log n plus the children it really meets, not n.
#include <vector>

#include "core/bvh.hpp"
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
  // A crossing of one child, with the child's index.
  struct Candidate {
    Crossing crossing;
    size_t child;
  };
  // Children's boxes in a hierarchy, and the children whose boxes are infinite.
  struct Index {
    Bvh bvh;
    std::vector<uint32_t> bounded;    // BVH primitive -> child
    std::vector<uint32_t> unbounded;  // always asked
  };

  void build_indexes();
  // Whether a crossing of child `from` at p survives (its normal flips in a difference).
  bool keeps(size_t from, const Vec3& p) const;
  std::optional<Crossing> kept_crossing(const Candidate& candidate, const Ray& ray) const;
  // Whether p is inside some child other than `skip1` and `skip2`.
  bool inside_other(const Vec3& p, size_t skip1, size_t skip2) const;
  // Whether the ray meets the bounds within [tmin, tmax].
  bool meets(const Ray& ray, double tmin, double tmax) const;
  // The crossings of the children the ray meets, ascending in t (ties: child order).
  void child_crossings(const Ray& ray, double tmin, double tmax, std::vector<Candidate>& out,
                       TraceStats& stats) const;
  std::optional<Crossing> first_of_union(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const;

  scene::CsgOperation operation_;
  std::vector<ShapePtr> children_;
  std::vector<Box3> child_bounds_, child_inside_bounds_;  // each child's, cached
  Index surfaces_, insides_;  // over child_bounds_ and child_inside_bounds_
  Box3 bounds_, inside_bounds_;
};

}  // namespace convray::geometry
