#include "geometry/superellipsoid.hpp"

#include <algorithm>
#include <cmath>

#include "core/box.hpp"
#include "core/bracket_refine.hpp"

namespace convray::geometry {

namespace {

// Bisection steps: each halves the bracket, so 60 reach the last bits of a unit-sized span.
constexpr int kBisections = 60;
// Samples per piece of the ray between coordinate planes for the non-convex shapes: enough
// that the thinnest spikes of the example scenes (exponents up to 5) are not stepped over.
constexpr int kSamples = 64;

// |v|^power, with 0^power = 0 for every positive power.
double magnitude_power(double v, double power) {
  const double a = std::abs(v);
  return a == 0.0 ? 0.0 : std::pow(a, power);
}

}  // namespace

SuperellipsoidShape::SuperellipsoidShape(double e, double n, SurfaceInfoPtr surface)
    : p_(2.0 / e), q_(2.0 / n), r_(e / n), surface_(std::move(surface)) {}

Box3 SuperellipsoidShape::bounds() const { return Box3{Vec3(-1.0), Vec3(1.0)}; }

double SuperellipsoidShape::implicit_value(const Vec3& p) const {
  const double across = magnitude_power(p.x, p_) + magnitude_power(p.y, p_);
  return magnitude_power(across, r_) + magnitude_power(p.z, q_) - 1.0;
}

// The gradient divided by q (a common positive factor): q A^(r-1) |x|^(p-1) sign(x) for x
// and y, with A = |x|^p + |y|^p, and q |z|^(q-1) sign(z) for z.
Vec3 SuperellipsoidShape::outward_normal(const Vec3& p) const {
  const double across = magnitude_power(p.x, p_) + magnitude_power(p.y, p_);
  const double outer = across == 0.0 ? 0.0 : std::pow(across, r_ - 1.0);
  auto term = [](double v, double power) { return std::copysign(magnitude_power(v, power), v); };
  Vec3 g(outer * term(p.x, p_ - 1.0), outer * term(p.y, p_ - 1.0), term(p.z, q_ - 1.0));
  const double length = glm::length(g);
  if (std::isfinite(length) && length > 0.0) return g / length;
  // On an axis where an exponent below 1 makes the slope infinite: the axis' own direction.
  const Vec3 a = glm::abs(p);
  if (a.z >= a.x && a.z >= a.y) return Vec3(0.0, 0.0, p.z < 0.0 ? -1.0 : 1.0);
  if (a.x >= a.y) return Vec3(p.x < 0.0 ? -1.0 : 1.0, 0.0, 0.0);
  return Vec3(0.0, p.y < 0.0 ? -1.0 : 1.0, 0.0);
}

double SuperellipsoidShape::slope_along(const Ray& ray, double t) const {
  return glm::dot(outward_normal(ray.at(t)), ray.direction);
}

// f(lo) and f(hi) differ in sign: the crossing between them.
double SuperellipsoidShape::refine(const Ray& ray, double lo, double hi) const {
  const bool lo_inside = implicit_value(ray.at(lo)) < 0.0;
  return bisect_to_rounding(
      lo, hi, [&](double t) { return (implicit_value(ray.at(t)) < 0.0) == lo_inside; },
      kBisections);
}

// Convex f: its minimum along [lo, hi] by bisection on the slope's sign, then a root on
// each side where f changes sign.
void SuperellipsoidShape::convex_roots(const Ray& ray, double lo, double hi,
                                       std::vector<double>& roots) const {
  double lowest;
  if (slope_along(ray, lo) >= 0.0) {
    lowest = lo;
  } else if (slope_along(ray, hi) <= 0.0) {
    lowest = hi;
  } else {
    lowest = bisect_to_rounding(
        lo, hi, [&](double t) { return slope_along(ray, t) < 0.0; }, kBisections);
  }
  if (!(implicit_value(ray.at(lowest)) < 0.0)) return;
  if (implicit_value(ray.at(lo)) >= 0.0) roots.push_back(refine(ray, lo, lowest));
  if (implicit_value(ray.at(hi)) >= 0.0) roots.push_back(refine(ray, lowest, hi));
}

// Any f: the span is cut where the ray crosses a coordinate plane, each piece sampled and
// every sign change refined.
void SuperellipsoidShape::sampled_roots(const Ray& ray, double lo, double hi,
                                        std::vector<double>& roots) const {
  double cuts[5] = {lo, hi, lo, lo, lo};
  int count = 2;
  for (int axis = 0; axis < 3; ++axis) {
    if (ray.direction[axis] == 0.0) continue;
    const double t = -ray.origin[axis] / ray.direction[axis];
    if (t > lo && t < hi) cuts[count++] = t;
  }
  std::sort(cuts, cuts + count);
  for (int piece = 0; piece + 1 < count; ++piece) {
    const double a = cuts[piece], b = cuts[piece + 1];
    double t0 = a;
    bool in0 = implicit_value(ray.at(t0)) < 0.0;
    for (int i = 1; i <= kSamples; ++i) {
      const double t1 = i == kSamples ? b : a + (b - a) * i / kSamples;
      const bool in1 = implicit_value(ray.at(t1)) < 0.0;
      if (in1 != in0) roots.push_back(refine(ray, t0, t1));
      t0 = t1;
      in0 = in1;
    }
  }
}

void SuperellipsoidShape::crossings(const Ray& ray, double tmin, double tmax,
                                    std::vector<Crossing>& out, TraceStats& /*stats*/) const {
  Box3 box = bounds();
  box.lo -= 1e-9;
  box.hi += 1e-9;
  double enter = tmin, leave = tmax;
  if (!clip_to_box(ray, box, enter, leave)) return;
  std::vector<double> roots;
  if (p_ >= 1.0 && q_ >= 1.0) {
    convex_roots(ray, enter, leave, roots);
  } else {
    sampled_roots(ray, enter, leave, roots);
  }
  for (double t : roots)
    add_crossing(t, outward_normal(ray.at(t)), surface_.get(), tmin, tmax, out);
}

bool SuperellipsoidShape::inside(const Vec3& p) const { return implicit_value(p) < 0.0; }

}  // namespace convray::geometry
