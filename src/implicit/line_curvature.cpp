#include "implicit/line_curvature.hpp"

#include <algorithm>
#include <cmath>
#include <array>

namespace convray::implicit {
namespace {

// The range, mean and variance of u.(q - origin) over a point, a segment or a triangle given
// by its N corners (u.x is linear in q: its extremes are at corners, its mean is theirs, and
// its variance is the sum over corner pairs of the squared difference, / 12 on a segment,
// / 36 on a triangle).
struct Extent {
  double lo = 0.0, hi = 0.0, mean = 0.0, var = 0.0;
};
template <size_t N>
Extent extent_along(const Ray& ray, const std::array<Vec3, N>& corners) {
  double along[N];
  for (size_t k = 0; k < N; ++k) along[k] = glm::dot(corners[k] - ray.origin, ray.direction);
  Extent e{along[0], along[0], along[0], 0.0};
  double pairs = 0.0;
  for (size_t i = 1; i < N; ++i) {
    e.lo = std::min(e.lo, along[i]);
    e.hi = std::max(e.hi, along[i]);
    e.mean += along[i];
    for (size_t j = 0; j < i; ++j) pairs += (along[i] - along[j]) * (along[i] - along[j]);
  }
  e.mean *= 1.0 / double(N);
  e.var = pairs * (N == 3 ? 1.0 / 36.0 : 1.0 / 12.0);
  return e;
}

}  // namespace

LineCurvature::LineCurvature(const ConvolutionSurface::Impl& s, uint32_t id, const Ray& ray) {
  double strength = 0.0, radius = 1.0;
  Extent extent;
  measure_ = 1.0;
  has_extent_ = has_moments_ = true;
  if (id < s.capsule_base) {  // points and blob spheres: K itself
    strength = s.sphere_strengths[id];
    radius = s.sphere_radii[id];
    extent = extent_along(ray, std::array<Vec3, 1>{s.sphere_centers[id]});
  } else if (id < s.arc_base) {
    const uint32_t i = id - s.capsule_base;
    const field::Segment& seg = s.capsules[i];
    strength = s.capsule_strengths[i];
    radius = s.capsule_radii[i];
    extent = extent_along(ray, std::array<Vec3, 2>{seg.a, seg.b});
    // A blob cylinder is K of the squared distance d2 to the segment: K'' = K_dd d2'^2 +
    // K_d d2'' with 0 <= K_dd = 2/R^4, -2/R^2 <= K_d <= 0, |d2'| <= 2 |u.x| (x from the
    // nearest point) and 0 <= d2'' <= 2: up to 8 (u.x)^2/R^4, down to 4/R^2, as a point.
    if (s.capsule_is_blob[i]) {
      has_moments_ = false;
    } else {
      length_ = glm::length(seg.b - seg.a);
      measure_ = std::min(length_, 2.0 * radius);
    }
  } else if (id < s.triangle_base) {
    const uint32_t i = id - s.arc_base;
    strength = s.arc_strengths[i];
    radius = s.arc_radii[i];
    measure_ = std::min(s.arcs[i].angle * s.arcs[i].radius, 2.0 * kPi * radius);
    has_extent_ = has_moments_ = false;
  } else {
    const uint32_t i = id - s.triangle_base;
    const ConvolutionSurface::Impl::Group& g = s.group_of(i);
    *this = LineCurvature(s.triangles[i], s.frames[i], g.strength, g.radius, ray);
    return;
  }
  lo_ = extent.lo;
  hi_ = extent.hi;
  mean_ = extent.mean;
  var_ = extent.var;
  weight_ = std::abs(strength);
  radius_ = radius;
  r2_ = radius * radius;
  flipped_ = strength < 0.0;
  down_anywhere_ = weight_ * 4.0 * measure_ / r2_;  // what bend_down gives for any window
}

LineCurvature::LineCurvature(const field::Triangle& tri, const field::TriangleFrame& frame,
                             double strength, double radius, const Ray& ray)
    : weight_(std::abs(strength)),
      radius_(radius),
      r2_(radius * radius),
      // A triangle with no area, or one too large to have a finite one, has no field (the
      // batch gives it weight 0): nothing to bend.
      measure_(frame.has_area() ? frame.area : 0.0),
      length_(measure_),
      has_extent_(true),
      has_moments_(true),
      limit_(2.0 * kPi),
      flipped_(strength < 0.0),
      triangle_(frame.has_area()) {  // no area, no field
  const Extent extent = extent_along(ray, std::array<Vec3, 3>{tri.a, tri.b, tri.c});
  lo_ = extent.lo;
  hi_ = extent.hi;
  mean_ = extent.mean;
  var_ = extent.var;
  // The plane's tilt along the line sets the downward limit (the table's twin takes it from
  // the same terms).
  if (triangle_) reach_ = accel::triangle_reach(ray.origin, ray.direction, tri, frame);
  down_limit_ = triangle_down_limit(reach_);
  down_anywhere_ = triangle_down_anywhere(weight_, measure_, r2_, down_limit_);
}

double LineCurvature::area_within(double a, double b) const {
  const auto& h = reach_.height;
  const auto& o = reach_.outside;
  return triangle_area_within(radius_, measure_,
                              triangle_plane_nearest(h[0], h[1], o[0][0], o[0][1], o[1][0],
                                                     o[1][1], o[2][0], o[2][1], a, b));
}

double LineCurvature::bend_down(double a, double b) const {
  if (!triangle_) return weight_ * 4.0 * measure_ / r2_;
  const auto& h = reach_.height;
  const auto& o = reach_.outside;
  return triangle_down_bend(weight_, radius_, 1.0 / r2_, measure_, down_limit_,
                            inverse_limit(down_limit_), h[0], h[1], o[0][0],
                            o[0][1], o[1][0], o[1][1], o[2][0], o[2][1], reach_.along[0],
                            reach_.along[1], a, b);
}

LineCurvature::DownTerms LineCurvature::down_terms() const {
  return {weight_, radius_, r2_, measure_, down_limit_, down_anywhere_, triangle_, reach_};
}

LineCurvature::DownTerms LineCurvature::triangle_down_terms(const field::Triangle& tri,
                                                            const field::TriangleFrame& frame,
                                                            double strength, double radius,
                                                            const Ray& ray) {
  if (!frame.has_area()) return triangle_down_terms(0.0, strength, radius, TriangleReach{});
  return triangle_down_terms(2.0 * frame.area, strength, radius,
                             accel::triangle_reach(ray.origin, ray.direction, tri, frame));
}

}  // namespace convray::implicit
