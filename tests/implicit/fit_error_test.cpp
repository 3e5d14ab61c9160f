// The degree-6 fit of one primitive's exact field along a ray (Eqs. 13-19, interval_fit.hpp)
// and its error estimate as docs/ray-tracing.md states it: 3 x the larger discrepancy between
// the fit and the exact field at s = 1/8 and 7/8, the piece split at its middle while that
// exceeds 1e-3 T, at most 4 levels deep. Checked against the error measured by sampling each
// piece densely, on random segments, triangles, arcs and blob cylinders and random rays.
// The pieces are split by the tracer's own rule (interval_fit.hpp: fit_error_estimate and
// fit_needs_split, which surface_roots.cpp calls); what is checked is that estimate against
// the error measured on the exact field.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "implicit/convolution_surface.hpp"
#include "implicit/interval_fit.hpp"
#include "implicit/surface_impl.hpp"

namespace convray::implicit {
namespace {

constexpr int kSamples = 400;  // per piece, for the measured error

struct Piece {
  double t0, t1, estimate, measured;
  int depth;
};

// One primitive's exact field along a ray, fitted the documented way; every final piece with
// its estimate and the error measured on kSamples + 1 points.
class FitChecker {
 public:
  FitChecker(const ConvolutionSurface::Impl& s, const Ray& ray) : s_(s), ray_(ray) {}

  std::vector<Piece> fit(const accel::SupportInterval& iv) {
    pieces_.clear();
    const uint32_t id = iv.primitive;
    const double width = iv.exit - iv.enter;
    // An arc's conservative interval is fitted in pieces no longer than 2R.
    double count = 1.0;
    if (id >= s_.arc_base && id < s_.triangle_base) {
      count = std::max(1.0, std::ceil(width / (2.0 * s_.arc_radii[id - s_.arc_base])));
    }
    double t0 = iv.enter, v0 = 0.0, g0 = 0.0;
    for (double k = 1.0; k <= count; k += 1.0) {
      const double t1 = k == count ? iv.exit : iv.enter + width * (k / count);
      const double v1 = k < count ? f(id, t1) : 0.0, g1 = k < count ? slope(id, t1) : 0.0;
      const double w = t1 - t0;
      const double q[3] = {f(id, t0 + 0.25 * w), f(id, t0 + 0.5 * w), f(id, t0 + 0.75 * w)};
      fit(id, t0, t1, v0, g0, v1, g1, q, 0);
      t0 = t1;
      v0 = v1;
      g0 = g1;
    }
    return pieces_;
  }

 private:
  double f(uint32_t id, double t) const { return s_.value(id, ray_.at(t)); }
  double slope(uint32_t id, double t) const {
    return glm::dot(s_.sample(id, ray_.at(t)).gradient, ray_.direction);
  }

  void fit(uint32_t id, double t0, double t1, double v0, double g0, double v1, double g1,
           const double q[3], int depth) {
    const double w = t1 - t0;
    const Poly6 poly = fit_degree6({v0, g0, v1, g1, {q[0], q[1], q[2]}}, w);
    const double e1 = f(id, t0 + w / 8.0), e7 = f(id, t0 + 7.0 * w / 8.0);
    const double estimate = fit_error_estimate(poly, e1, e7);
    if (fit_needs_split(estimate, s_.threshold, depth)) {
      const double mid = t0 + 0.5 * w, g_mid = slope(id, mid);
      const double left[3] = {e1, q[0], f(id, t0 + 3.0 * w / 8.0)};
      const double right[3] = {f(id, t0 + 5.0 * w / 8.0), q[2], e7};
      fit(id, t0, mid, v0, g0, q[1], g_mid, left, depth + 1);
      fit(id, mid, t1, q[1], g_mid, v1, g1, right, depth + 1);
      return;
    }
    double measured = 0.0;
    for (int j = 0; j <= kSamples; ++j) {
      const double s = double(j) / kSamples;
      measured = std::max(measured, std::abs(evaluate(poly, s) - f(id, t0 + s * w)));
    }
    pieces_.push_back({t0, t1, estimate, measured, depth});
  }

  const ConvolutionSurface::Impl& s_;
  const Ray& ray_;
  std::vector<Piece> pieces_;
};

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

enum class Kind { segment, triangle, arc, blob_cylinder };

// One primitive of the given kind near the origin, strength 1, radius R; T a fraction of the
// field's largest value, so that the surface lies somewhere inside the support.
scene::ConvolutionObject one_primitive(Kind kind, std::mt19937_64& rng, double R) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  scene::ConvolutionObject o;
  const Vec3 a = random_unit(rng), b = (0.2 + 2.0 * unit(rng)) * random_unit(rng),
             c = (0.2 + 2.0 * unit(rng)) * random_unit(rng);
  double peak = 1.0;
  switch (kind) {
    case Kind::segment:
      o.segments.push_back({{a, b}, {1.0, R}});
      peak = 16.0 / 15.0 * R;  // the integral across a long segment
      break;
    case Kind::triangle:
      o.meshes.push_back({{{a, b, c}}, {1.0, R}});
      peak = kPi / 3.0 * R * R;  // the plane's field at height 0
      break;
    case Kind::arc: {
      // Rings from R/2 to 8 R: on the wide ones most of the conservative support interval
      // lies outside the support.
      field::Arc arc;
      arc.center = 0.3 * a;
      arc.axis = random_unit(rng);
      arc.start = glm::normalize(glm::cross(arc.axis, random_unit(rng)));
      arc.radius = R * (0.5 + 7.5 * unit(rng));
      arc.angle = unit(rng) < 0.3 ? 2.0 * kPi : 0.3 + 5.5 * unit(rng);
      o.arcs.push_back({arc, {1.0, R}});
      peak = 16.0 / 15.0 * R;
      break;
    }
    case Kind::blob_cylinder:
      o.blob_cylinders.push_back({a, b, {1.0, R}});
      peak = 1.0;
  }
  o.threshold = (0.1 + 0.6 * unit(rng)) * peak;
  return o;
}

// Every final piece of 800 random rays through 32 random primitives of one kind. The estimate
// is no proof (docs/ray-tracing.md, "Known limits"), and it does fall short: on under 1 % of
// pieces, mostly ones just under the split tolerance whose error is 2 to 4 times the estimate.
// So what is asserted is that it holds on at least 99 % of pieces and, where it does not,
// misses by less than twice the split tolerance: errors of the size the tracer's widening of
// brackets (step 4) is there to absorb, not a bump the fit never saw.
void check_estimate(Kind kind, const char* name, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int pieces = 0, short_of_measured = 0;
  double worst_shortfall = 0.0;  // of T
  for (int scene = 0; scene < 32; ++scene) {
    const double R = 0.2 + 1.5 * unit(rng);
    const ConvolutionSurface surface(one_primitive(kind, rng, R));
    const ConvolutionSurface::Impl& impl = surface.impl();
    for (int i = 0; i < 25; ++i) {
      const Vec3 origin = 8.0 * random_unit(rng);
      const Ray ray{origin, glm::normalize(1.5 * unit(rng) * random_unit(rng) - origin)};
      std::vector<accel::SupportInterval> intervals;
      impl.index->intersect(ray.origin, ray.direction, 0.0, INFINITY, intervals);
      FitChecker checker(impl, ray);
      for (const auto& iv : intervals) {
        if (!(iv.exit > iv.enter)) continue;
        for (const Piece& p : checker.fit(iv)) {
          ++pieces;
          const double shortfall = (p.measured - p.estimate) / impl.threshold;
          if (shortfall > 1e-12) ++short_of_measured;
          worst_shortfall = std::max(worst_shortfall, shortfall);
        }
      }
    }
  }
  std::printf(
      "[ fit ] %-14s %5d pieces, estimate below the measured error on %d, "
      "by at most %.3g T\n",
      name, pieces, short_of_measured, worst_shortfall);
  EXPECT_GT(pieces, 1000);
  EXPECT_LE(short_of_measured, pieces / 100);
  EXPECT_LE(worst_shortfall, 2.0 * kFitTolerance);
}

TEST(FitError, EstimateBoundsTheErrorOnSegments) { check_estimate(Kind::segment, "segment", 1421); }
TEST(FitError, EstimateBoundsTheErrorOnTriangles) {
  check_estimate(Kind::triangle, "triangle", 1422);
}
TEST(FitError, EstimateBoundsTheErrorOnArcs) { check_estimate(Kind::arc, "arc", 1423); }
TEST(FitError, EstimateBoundsTheErrorOnBlobCylinders) {
  check_estimate(Kind::blob_cylinder, "blob cylinder", 1424);
}

}  // namespace
}  // namespace convray::implicit
