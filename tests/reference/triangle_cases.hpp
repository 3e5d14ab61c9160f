#pragma once
// Random triangle/point/R cases for the triangle field tests, one generator per configuration
// of the clipping circle (centre O, radius r0, in the triangle's plane) against the triangle,
// and an independent classifier that says which configuration a case really is. Generators
// aim at a configuration; only the classifier's verdict is counted.
#include <array>
#include <random>
#include <span>
#include <string_view>

#include "util/math.hpp"

namespace convray::reference {

struct TriangleCase {
  Vec3 p, a, b, c;
  double radius = 1.0;
  std::string_view generator;
  bool exact = false;  // built on a dyadic grid in an axis-aligned frame: relations hold exactly
};

// Rows of the coverage table. A case belongs to one Fig. 1 row (when the circle is defined and
// not degenerate) and to any number of the other rows.
enum class TriangleFeature : int {
  // Paper Fig. 1: number of circle/edge intersection points.
  kZeroPointsTriangleInsideDisk,
  kZeroPointsDiskInsideTriangle,
  kZeroPointsDisjoint,
  kTwoPointsOneEdgeTwice,
  kTwoPointsTwoEdgesOnce,
  kFourPointsTwoEdgesTwice,
  kFourPointsOneEdgeTwiceTwoEdgesOnce,
  kSixPoints,
  // Where P is.
  kOOutsideTriangle,
  kOInsideTriangle,
  kPInPlane,
  kOOnEdge,
  kOOnVertex,
  kSphereMissesPlane,
  kHNearRadius,
  // Degenerate contacts between the circle and the triangle.
  kEdgeTangentToCircle,
  kVertexOnCircle,
  // Triangle shape.
  kNeedleSliver,
  kCapSliver,
  kZeroArea,
  kLargeTriangle,
  // Scale and precision.
  kRadiusBelowTenth,
  kRadiusTenthToTen,
  kRadiusAboveTen,
  kFarFromOrigin,
  kCount
};
inline constexpr int kTriangleFeatureCount = static_cast<int>(TriangleFeature::kCount);

std::string_view feature_name(TriangleFeature feature);

struct TriangleClassification {
  std::array<bool, kTriangleFeatureCount> has{};
  std::array<int, 3> crossings{};  // circle/edge intersection points per edge
  // Distance, in units of R, from P to the nearest place where the field is not smooth or the
  // plane (|h|, R - |h|, |  |P - V| - R |, | dist(P, edge) - R |); 0 for zero-area triangles;
  // |h| - R when the sphere misses the plane.
  double smooth_margin = 0.0;

  bool operator[](TriangleFeature f) const { return has[static_cast<int>(f)]; }
};

// Independent geometry: intersections counted from the sphere/segment quadratic in 3-D,
// O inside/on the triangle from signed sub-areas, contacts within 1e-9 R.
TriangleClassification classify_triangle_case(const TriangleCase& tc);

struct TriangleGenerator {
  std::string_view name;
  TriangleCase (*make)(std::mt19937_64& rng);
};

// Every generator, each aimed at one configuration or degenerate feature.
std::span<const TriangleGenerator> triangle_generators();

}  // namespace convray::reference
