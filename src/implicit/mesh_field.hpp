#pragma once
// The convolution field of a whole polygon soup: the sum of every triangle's closed-form
// field with one radius and strength, evaluated through a point query so that only the
// triangles within R of the point are visited.
#include <optional>
#include <span>
#include <vector>

#include "field/triangle.hpp"
#include "field/triangle_batch.hpp"
#include "implicit/repeated_triangles.hpp"
#include "implicit/support_grid.hpp"

namespace convray::implicit {

class MeshField {
 public:
  // Exactly repeated triangles are summed once, times their count (repeated_triangles.hpp).
  MeshField(std::vector<field::Triangle> triangles, double radius, double strength = 1.0);

  double radius() const { return radius_; }
  double strength() const { return strength_; }
  size_t triangle_count() const { return total_; }  // as given, repeats included
  // The distinct triangles (each repeated one once) and how often each occurs.
  const std::vector<field::Triangle>& triangles() const { return triangles_; }
  const std::vector<double>& multiplicities() const { return weights_; }

  // Fast path: batched SIMD evaluation of the candidate triangles.
  double value(const Vec3& p) const;
  field::FieldSample field(const Vec3& p) const;
  // Exact twin: the scalar closed form on the same candidates, for tests and checks.
  field::FieldSample field_exact(const Vec3& p) const;

  const SupportGrid& grid() const { return grid_; }

  // The triangles whose support can contain p: the grid cell's list, culled by each
  // triangle's bounding sphere grown by R (cheap, and far tighter than the cell).
  void contributors(const Vec3& p, std::vector<uint32_t>& out) const;

 private:
  struct Distinct {
    std::vector<field::Triangle> triangles;
    std::vector<double> weights;  // multiplicities
    size_t total;                 // triangles as given
  };
  static Distinct distinct(std::vector<field::Triangle> triangles);
  MeshField(Distinct distinct, double radius, double strength);

  std::vector<field::Triangle> triangles_;
  std::vector<double> weights_;  // multiplicities
  size_t total_;
  field::TriangleBatch batch_;
  SupportGrid grid_;
  std::vector<double> sphere_x_, sphere_y_, sphere_z_, sphere_reach2_;  // (r_bound + R)^2
  double radius_;
  double strength_;
};

}  // namespace convray::implicit
