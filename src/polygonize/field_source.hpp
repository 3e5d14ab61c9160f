#pragma once
// What the polygonizer needs to know about a field: its value and exact gradient at any point,
// where it can be non-zero, and the threshold of the surface F = T. Any field fits: a
// convolution object, a single mesh's MeshField, a Cauchy-kernel object, a transformed one.
#include <functional>
#include <vector>

#include "field/sample.hpp"
#include "implicit/convolution_object.hpp"
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

// The closed axis-aligned box around each primitive's support (the skeleton grown by its
// radius R) of a convolution object: one per distinct triangle of each mesh (exact repeats
// share one), segment, arc, point and blob component.
std::vector<Box3> support_boxes(const implicit::ConvolutionObject& object);

// The box around the corners of `box` mapped by the affine `m` (conservative for any affine m).
Box3 transform_box(const Mat4& m, const Box3& box);

}  // namespace convray::polygonize
