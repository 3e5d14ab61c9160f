// The independent classifier of triangle cases (declared in triangle_cases.hpp): which paper
// Fig. 1 configuration, where O lies, which degenerate contacts and shapes a case has.
#include <algorithm>
#include <cmath>

#include "reference/triangle_cases.hpp"

namespace convray::reference {
namespace {

// Distance from the origin to the segment a-b.
double distance_to_segment(const Vec3& a, const Vec3& b) {
  const Vec3 edge = b - a;
  const double t = std::clamp(-glm::dot(a, edge) / glm::dot(edge, edge), 0.0, 1.0);
  return glm::length(a + t * edge);
}

// Circle/edge intersection points: parameters s in [0, 1] with |a + s (b - a)| = r0, a and b
// relative to O, found from the foot of the perpendicular from O (no cancellation for long
// edges): s = foot +- sqrt(r0^2 - distance^2) / |b - a|.
int circle_segment_crossings(const Vec3& a, const Vec3& b, double r0) {
  const Vec3 edge = b - a;
  const double length = glm::length(edge);
  const double foot = -glm::dot(a, edge) / (length * length);
  const double distance = glm::length(a + foot * edge);
  if (distance >= r0) return 0;
  const double half_chord = std::sqrt((r0 - distance) * (r0 + distance)) / length;
  int count = 0;
  for (double s : {foot - half_chord, foot + half_chord})
    if (s >= 0.0 && s <= 1.0) ++count;
  return count;
}

TriangleFeature fig1_configuration(const std::array<int, 3>& crossings, bool vertices_inside,
                                   bool o_inside) {
  std::array<int, 3> sorted = crossings;
  std::sort(sorted.begin(), sorted.end());  // ascending
  const int total = sorted[0] + sorted[1] + sorted[2];
  using F = TriangleFeature;
  switch (total) {
    case 0:
      if (vertices_inside) return F::kZeroPointsTriangleInsideDisk;
      return o_inside ? F::kZeroPointsDiskInsideTriangle : F::kZeroPointsDisjoint;
    case 2: return sorted[2] == 2 ? F::kTwoPointsOneEdgeTwice : F::kTwoPointsTwoEdgesOnce;
    case 4: return sorted[0] == 0 ? F::kFourPointsTwoEdgesTwice : F::kFourPointsOneEdgeTwiceTwoEdgesOnce;
    default: return F::kSixPoints;
  }
}

}  // namespace

std::string_view feature_name(TriangleFeature feature) {
  switch (feature) {
    case TriangleFeature::kZeroPointsTriangleInsideDisk: return "0 points: triangle inside the disk";
    case TriangleFeature::kZeroPointsDiskInsideTriangle: return "0 points: disk inside the triangle";
    case TriangleFeature::kZeroPointsDisjoint: return "0 points: disk and triangle disjoint";
    case TriangleFeature::kTwoPointsOneEdgeTwice: return "2 points: one edge cut twice";
    case TriangleFeature::kTwoPointsTwoEdgesOnce: return "2 points: two edges cut once";
    case TriangleFeature::kFourPointsTwoEdgesTwice: return "4 points: two edges cut twice";
    case TriangleFeature::kFourPointsOneEdgeTwiceTwoEdgesOnce: return "4 points: one edge twice, two once";
    case TriangleFeature::kSixPoints: return "6 points: every edge cut twice";
    case TriangleFeature::kOOutsideTriangle: return "O outside the triangle (P beside)";
    case TriangleFeature::kOInsideTriangle: return "O inside the triangle (P above)";
    case TriangleFeature::kPInPlane: return "P in the plane (h = 0)";
    case TriangleFeature::kOOnEdge: return "O on an edge";
    case TriangleFeature::kOOnVertex: return "O on a vertex";
    case TriangleFeature::kSphereMissesPlane: return "outside support: |h| >= R";
    case TriangleFeature::kHNearRadius: return "h close to R (r0 < R/100)";
    case TriangleFeature::kEdgeTangentToCircle: return "edge tangent to the circle";
    case TriangleFeature::kVertexOnCircle: return "vertex on the circle";
    case TriangleFeature::kNeedleSliver: return "needle sliver";
    case TriangleFeature::kCapSliver: return "cap sliver";
    case TriangleFeature::kZeroArea: return "zero-area triangle";
    case TriangleFeature::kLargeTriangle: return "large triangle (longest edge > 10 R)";
    case TriangleFeature::kRadiusBelowTenth: return "R in [1e-3, 0.1)";
    case TriangleFeature::kRadiusTenthToTen: return "R in [0.1, 10]";
    case TriangleFeature::kRadiusAboveTen: return "R in (10, 1e3]";
    case TriangleFeature::kFarFromOrigin: return "far from the origin (|P| > 100 R)";
    case TriangleFeature::kCount: break;
  }
  return "?";
}

TriangleClassification classify_triangle_case(const TriangleCase& tc) {
  using F = TriangleFeature;
  TriangleClassification out;
  const auto mark = [&out](F feature) { out.has[static_cast<int>(feature)] = true; };
  const double radius = tc.radius;

  // Scale and precision.
  mark(radius < 0.1 ? F::kRadiusBelowTenth : radius <= 10.0 ? F::kRadiusTenthToTen : F::kRadiusAboveTen);
  if (glm::length(tc.p) > 100.0 * radius) mark(F::kFarFromOrigin);

  // Shape, with P at the origin.
  const std::array<Vec3, 3> v = {tc.a - tc.p, tc.b - tc.p, tc.c - tc.p};
  const Vec3 area_normal = glm::cross(v[1] - v[0], v[2] - v[0]);
  const double twice_area = glm::length(area_normal);
  if (glm::cross(tc.b - tc.a, tc.c - tc.a) == Vec3(0.0) || twice_area == 0.0) {
    mark(F::kZeroArea);
    return out;
  }
  std::array<double, 3> edge_length;
  for (int i = 0; i < 3; ++i) edge_length[i] = glm::length(v[(i + 1) % 3] - v[i]);
  std::sort(edge_length.begin(), edge_length.end());
  if (edge_length[2] > 10.0 * radius) mark(F::kLargeTriangle);
  if (twice_area < 1e-3 * edge_length[2] * edge_length[2])
    mark(edge_length[0] < 1e-2 * edge_length[2] ? F::kNeedleSliver : F::kCapSliver);

  // Height of P over the plane and the clipping circle.
  const Vec3 normal = area_normal / twice_area;
  const double h = -(glm::dot(normal, v[0]) + glm::dot(normal, v[1]) + glm::dot(normal, v[2])) / 3.0;
  if (std::abs(h) <= 1e-10 * radius) mark(F::kPInPlane);
  if (std::abs(h) >= radius) {
    mark(F::kSphereMissesPlane);
    out.smooth_margin = (std::abs(h) - radius) / radius;
    return out;
  }
  const double r0 = std::sqrt((radius - std::abs(h)) * (radius + std::abs(h)));
  if (r0 < 0.01 * radius) mark(F::kHNearRadius);

  // O against the triangle: contacts within 1e-9 R, otherwise signed sub-areas.
  const double contact = 1e-9 * radius;
  const Vec3 o = -h * normal;
  std::array<Vec3, 3> w;  // vertices relative to O
  for (int i = 0; i < 3; ++i) w[i] = v[i] - o;
  bool on_vertex = false, on_edge = false, inside = true;
  for (int i = 0; i < 3; ++i) {
    const Vec3& from = w[(i + 1) % 3];
    const Vec3& to = w[(i + 2) % 3];
    on_vertex = on_vertex || glm::length(w[i]) <= contact;
    on_edge = on_edge || distance_to_segment(from, to) <= contact;
    inside = inside && glm::dot(glm::cross(from, to), normal) > 0.0;
  }
  if (on_vertex) {
    mark(F::kOOnVertex);
  } else if (on_edge) {
    mark(F::kOOnEdge);
  } else {
    mark(inside ? F::kOInsideTriangle : F::kOOutsideTriangle);
  }

  // The circle against the edges; contacts measured in the plane, against r0.
  bool degenerate = false;
  bool vertices_inside = true;
  double margin = std::min(std::abs(h), radius - std::abs(h));
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (std::abs(glm::length(w[i]) - r0) <= contact) {
      mark(F::kVertexOnCircle);
      degenerate = true;
    }
    const Vec3 edge = w[j] - w[i];
    const double foot = -glm::dot(w[i], edge) / glm::dot(edge, edge);
    if (foot > 0.0 && foot < 1.0 && std::abs(glm::length(w[i] + foot * edge) - r0) <= contact) {
      mark(F::kEdgeTangentToCircle);
      degenerate = true;
    }
    out.crossings[i] = circle_segment_crossings(w[i], w[j], r0);
    vertices_inside = vertices_inside && glm::length(v[i]) < radius;
    margin = std::min({margin, std::abs(glm::length(v[i]) - radius),
                       std::abs(distance_to_segment(v[i], v[j]) - radius)});
  }
  out.smooth_margin = margin / radius;
  const int total = out.crossings[0] + out.crossings[1] + out.crossings[2];
  if (!degenerate && total % 2 == 0) mark(fig1_configuration(out.crossings, vertices_inside, inside && !on_edge));
  return out;
}

}  // namespace convray::reference
