#pragma once
// POV-Ray's `height_field`: a grid of heights over the unit square of the x-z plane, two
// triangles per cell, as the povray binary draws it (measured with trace() on small images):
//   vertex (i, j) lies at x = i / (columns - 1), z = j / (rows - 1), y = its height in [0, 1];
//   the image's top row is at z = 1, its bottom row at z = 0;
//   each cell is split along its diagonal from (x1, z0) to (x0, z1) (every cell of a 5 x 5
//   image of random heights, two points each, against both diagonals);
//   a point is inside when it lies over the unit square and below the surface (at any depth);
//   `water_level w`: the surface below y = w is not drawn.
// The triangles go through the mesh's BVH (triangle_mesh.hpp).
#include <memory>

#include "geometry/triangle_mesh.hpp"

namespace convray::geometry {

class HeightFieldShape final : public Shape {
 public:
  HeightFieldShape(const scene::HeightField& field, SurfaceInfoPtr surface);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;

  // The surface's height over (x, z) in the unit square, on the cell's triangles.
  double surface_height(double x, double z) const;

 private:
  double at(int i, int j) const { return heights_[size_t(j) * size_t(columns_) + size_t(i)]; }

  int columns_, rows_;
  std::vector<double> heights_;
  double water_level_;
  std::unique_ptr<TriangleMeshShape> mesh_;
};

// The triangles (and, when `field.smooth`, the vertex normals) of a height field.
scene::TriangleMesh height_field_mesh(const scene::HeightField& field);

}  // namespace convray::geometry
