#pragma once
// POV-Ray's `triangle`, `smooth_triangle`, `mesh` and `mesh2`: flat triangles, or normals
// interpolated from the vertices' (smooth), each face with its own texture or the object's.
// A mesh with an `inside_vector` is a solid: a point is inside when a ray from it along that
// vector crosses the mesh an odd number of times. Without one the mesh has no inside.
//
// Rays go through a BVH of the triangles (core/bvh.hpp); crossings_brute_force() is its slow
// exact twin.
#include <array>
#include <optional>
#include <vector>

#include "core/bvh.hpp"
#include "geometry/primitive.hpp"
#include "scene/object.hpp"

namespace convray::geometry {

class TriangleMeshShape final : public Shape {
 public:
  // surfaces[0] is the object's; surfaces[1 + k] that of the mesh's texture k. Throws
  // std::invalid_argument on an index out of range. Faces of zero area are dropped.
  TriangleMeshShape(const scene::TriangleMesh& mesh, std::vector<SurfaceInfoPtr> surfaces);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

  // The same crossings as crossings(), by testing every triangle.
  void crossings_brute_force(const Ray& ray, double tmin, double tmax,
                             std::vector<Crossing>& out) const;
  size_t triangle_count() const { return faces_.size(); }

 private:
  struct Face {
    Vec3 a, edge1, edge2;            // a, b - a, c - a
    std::array<int32_t, 3> normals;  // into normals_; -1: flat
    uint32_t surface;                // into surfaces_
  };
  struct Hit {
    double t, u, v;
  };

  static bool intersect(const Face& face, const Ray& ray, double tmin, double tmax, Hit& hit);
  Crossing make_crossing(const Face& face, const Hit& hit) const;
  size_t count_crossings(const Ray& ray) const;

  std::vector<Face> faces_;
  std::vector<Vec3> normals_;
  std::vector<SurfaceInfoPtr> surfaces_;
  std::optional<Vec3> inside_direction_;  // unit
  Bvh bvh_;
};

}  // namespace convray::geometry
