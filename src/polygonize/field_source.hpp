#pragma once
// What the polygonizer needs to know about a field: its value and exact gradient at any point,
// where it can be non-zero, and the threshold of the surface F = T. Any field fits: a
// convolution object, a single mesh's MeshField, a Cauchy-kernel object, a transformed one.
#include <functional>
#include <span>
#include <vector>

#include "field/sample.hpp"
#include "field/triangle.hpp"
#include "util/math.hpp"

namespace convray::polygonize {

struct FieldSource {
  // F and grad F at p; called from several threads at once, so it must be thread safe.
  std::function<field::FieldSample(const Vec3&)> field;
  // F alone, where a faster evaluator than `field` exists (optional).
  std::function<double(const Vec3&)> value;
  // F = 0 outside the union of these closed boxes (each primitive's support, or its
  // truncation box): the polygonizer visits nothing else.
  std::vector<Box3> supports;
  // The surface is F = T and the solid F >= T; T must be positive so that the region outside
  // every support (F = 0) is outside the solid.
  double threshold = 1.0;

  double value_at(const Vec3& p) const { return value ? value(p) : field(p).value; }
};

// The closed box around each triangle's support (the triangle grown by `radius`): the
// supports of a soup's field (implicit::MeshField), whose surfaces give their own
// (implicit::Surface::support_boxes).
std::vector<Box3> triangle_support_boxes(std::span<const field::Triangle> triangles,
                                         double radius);

}  // namespace convray::polygonize
