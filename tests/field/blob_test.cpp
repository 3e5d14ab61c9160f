// Specification of the POV-Ray blob components: strength * (1 - d^2/r^2)^2 for d < r, else 0,
// with d the distance to the centre (sphere) or to the segment base-apex (cylinder: a capsule,
// distance to the axis along the body and to the nearer end point beyond it). Checked against
// the documented definition rewritten independently: the density expanded in the squared
// distance (our algebra), c0 d^4 + c1 d^2 + c2 with c0 = s/r^4, c1 = -2 s/r^2, c2 = s, its
// gradient 2 (2 c0 d^2 + c1) times the offset, and the cylinder as three pieces (a body measured
// in the axis's own frame, and a hemisphere at each end, as POV-Ray's documentation describes
// the capsule), none of it shared with field/blob.cpp's clamped projection onto the segment;
// and the gradient against a 5-point stencil.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "field/blob.hpp"
#include "reference/checks.hpp"
#include "reference/ratio_check.hpp"

namespace convray::field {
namespace {

constexpr unsigned long long kSeed = 0x626c6f622d303031ULL;  // "blob-001"
constexpr int kCaseCount = 3000;
constexpr double kValueTolerance = 1e-12;          // times |strength|
constexpr double kFormulaGradientTolerance = 1e-10;  // relative, floor |strength| / r
constexpr double kStencilTolerance = 1e-8;
constexpr double kStencilMargin = 0.02;  // times r: away from d = r and from the end planes
constexpr double kStencilStep = 1e-4;

// The documented density s (1 - d2/r^2)^2 of one component, expanded in the squared distance
// d2 and measured along `offset`: c0 d2^2 + c1 d2 + c2, zero from d2 = r^2 on.
FieldSample povray_density(const Vec3& offset, double d2, double radius, double strength) {
  if (d2 >= radius * radius) return {};
  const double c0 = strength / (radius * radius * radius * radius);
  const double c1 = -2.0 * strength / (radius * radius), c2 = strength;
  return {(c0 * d2 + c1) * d2 + c2, (2.0 * (2.0 * c0 * d2 + c1)) * offset};
}

FieldSample povray_sphere(const Vec3& p, const Vec3& center, double radius, double strength) {
  const Vec3 offset = p - center;
  return povray_density(offset, glm::dot(offset, offset), radius, strength);
}

// Where p lies along the axis, in lengths of the axis (0 at base, 1 at apex): for counting
// which region the cases fall in.
double axis_parameter(const Vec3& p, const Vec3& base, const Vec3& apex) {
  const Vec3 axis = apex - base;
  return glm::dot(p - base, axis) / glm::dot(axis, axis);
}

// The documented cylinder (a capsule): in the frame of the unit axis u, a point at height h along it is in the
// body for 0 <= h <= length (distance to the axis line), else in the hemisphere of the end it
// is beyond (distance to that end point).
FieldSample povray_cylinder(const Vec3& p, const Vec3& base, const Vec3& apex, double radius,
                            double strength) {
  const double length = glm::length(apex - base);
  const Vec3 u = (apex - base) / length;
  const double h = glm::dot(p - base, u);
  if (h < 0.0) return povray_sphere(p, base, radius, strength);
  if (h > length) return povray_sphere(p, apex, radius, strength);
  const Vec3 radial = (p - base) - h * u;
  return povray_density(radial, glm::dot(radial, radial), radius, strength);
}

struct Checks {
  reference::RatioCheck value, gradient, stencil;
  explicit Checks(const std::string& component)
      : value(component + " value vs POV-Ray's formula"),
        gradient(component + " gradient vs POV-Ray's formula"),
        stencil(component + " gradient vs 5-point stencil") {}

  void report() const {
    for (const reference::RatioCheck* check : {&value, &gradient, &stencil}) {
      std::printf("[ blob ] %-52s %5d cases, worst error/tolerance %.3g\n", check->what().c_str(),
                  check->checked(), check->worst().ratio);
      check->expect_no_failure();
    }
  }
};

// Compares one evaluation with POV-Ray's formula and, where smooth, the stencil.
template <class Evaluate>
void check(const Evaluate& evaluate, const FieldSample& povray, const Vec3& p, double radius,
           double strength, bool smooth, const std::string& inputs, Checks& checks) {
  const FieldSample sample = evaluate(p);
  const double floor = std::abs(strength) / radius;
  checks.value.add(reference::value_error_ratio(sample.value, povray.value, kValueTolerance, std::abs(strength)),
                   inputs);
  checks.gradient.add(
      reference::gradient_error_ratio(sample.gradient, povray.gradient, kFormulaGradientTolerance, floor), inputs);
  if (!smooth) return;
  const auto value = [&](const Vec3& q) { return evaluate(q).value; };
  if (const auto stencil = reference::five_point_gradient(value, p, kStencilStep * radius))
    checks.stencil.add(reference::gradient_error_ratio(sample.gradient, *stencil, kStencilTolerance, floor), inputs);
}

struct Random {
  std::mt19937_64 rng;
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Vec3 unit() {
    const double z = uniform(-1.0, 1.0), t = uniform(0.0, 2.0 * kPi), s = std::sqrt(1.0 - z * z);
    return {s * std::cos(t), s * std::sin(t), z};
  }
  double radius() { return std::pow(10.0, uniform(-3.0, 3.0)); }
  double strength() { return (uniform(0.0, 1.0) < 0.3 ? -1.0 : 1.0) * std::pow(10.0, uniform(-2.0, 1.0)); }
};

std::string describe(const Vec3& p, const Vec3& a, const Vec3& b, double radius, double strength) {
  return "p = " + reference::format_vec(p) + ", " + reference::format_vec(a) + ", " +
         reference::format_vec(b) + ", radius = " + reference::format_double(radius) +
         ", strength = " + reference::format_double(strength);
}

TEST(BlobSphere, MatchesThePovRayDefinition) {
  Random random{std::mt19937_64(reference::test_seed(kSeed))};
  Checks checks("blob_sphere_field");
  int inside = 0, outside = 0, negative = 0;
  for (int i = 0; i < kCaseCount; ++i) {
    const double radius = random.radius(), strength = random.strength();
    const Vec3 center = radius * Vec3(random.uniform(-50, 50), random.uniform(-50, 50), random.uniform(-50, 50));
    const Vec3 p = center + radius * random.uniform(0.0, 1.3) * random.unit();
    const double distance = glm::length(p - center);
    (distance < radius ? inside : outside) += 1;
    negative += strength < 0.0;
    check([&](const Vec3& q) { return blob_sphere_field(q, center, radius, strength); },
          povray_sphere(p, center, radius, strength), p, radius, strength,
          std::abs(distance - radius) > kStencilMargin * radius,
          describe(p, center, center, radius, strength), checks);
  }
  std::printf("[ blob ] sphere: %d inside, %d outside, %d negative strengths\n", inside, outside, negative);
  checks.report();
  EXPECT_GE(inside, 1000);
  EXPECT_GE(outside, 300);
  EXPECT_GE(negative, 500);
  EXPECT_GE(checks.stencil.checked(), 1000);
}

TEST(BlobCylinder, IsACapsuleMatchingThePovRayDefinition) {
  Random random{std::mt19937_64(reference::test_seed(kSeed) + 1)};
  Checks checks("blob_cylinder_field");
  enum { kBody, kBaseCap, kApexCap, kOutside, kNegative, kRegionCount };
  constexpr const char* kRegionNames[] = {"body", "base cap", "apex cap", "outside (0)", "negative strength"};
  std::array<int, kRegionCount> count{};
  for (int i = 0; i < kCaseCount; ++i) {
    const double radius = random.radius(), strength = random.strength();
    const Vec3 base = radius * Vec3(random.uniform(-50, 50), random.uniform(-50, 50), random.uniform(-50, 50));
    const double length = radius * std::pow(10.0, random.uniform(-2.0, 1.5));
    const Vec3 apex = base + length * random.unit();
    // Around the body or around either end.
    const double roll = random.uniform(0.0, 1.0);
    const Vec3 anchor = roll < 0.4 ? base + random.uniform(0.0, 1.0) * (apex - base) : roll < 0.7 ? base : apex;
    const Vec3 p = anchor + radius * random.uniform(0.0, 1.3) * random.unit();

    const double t = axis_parameter(p, base, apex);
    const FieldSample povray = povray_cylinder(p, base, apex, radius, strength);
    if (povray.value == 0.0) ++count[kOutside];
    else ++count[t < 0.0 ? kBaseCap : t > 1.0 ? kApexCap : kBody];
    count[kNegative] += strength < 0.0;
    const double distance = glm::length(p - (base + std::clamp(t, 0.0, 1.0) * (apex - base)));
    const bool smooth = std::abs(distance - radius) > kStencilMargin * radius &&
                        std::abs(t) * length > kStencilMargin * radius &&
                        std::abs(t - 1.0) * length > kStencilMargin * radius;
    check([&](const Vec3& q) { return blob_cylinder_field(q, base, apex, radius, strength); }, povray, p,
          radius, strength, smooth, describe(p, base, apex, radius, strength), checks);
  }
  for (int k = 0; k < kRegionCount; ++k) std::printf("[ blob ] cylinder %-20s %6d\n", kRegionNames[k], count[k]);
  checks.report();
  for (int k = 0; k < kRegionCount; ++k) EXPECT_GE(count[k], 300) << kRegionNames[k];
  EXPECT_GE(checks.stencil.checked(), 1000);
}

TEST(BlobCylinder, EndCapsAreHemispheresNotFlat) {
  // Beyond the apex, on the axis, the field is that of a sphere at the apex: a capsule.
  const Vec3 base(0.0), apex(0.0, 0.0, 2.0);
  for (double beyond : {0.1, 0.5, 0.9}) {
    const Vec3 p = apex + Vec3(0.0, 0.0, beyond);
    EXPECT_NEAR(blob_cylinder_field(p, base, apex, 1.0, 2.0).value,
                blob_sphere_field(p, apex, 1.0, 2.0).value, 1e-15);
    const Vec3 q = base + Vec3(0.3, 0.0, -beyond);
    EXPECT_NEAR(blob_cylinder_field(q, base, apex, 1.0, -1.5).value,
                blob_sphere_field(q, base, 1.0, -1.5).value, 1e-15);
  }
  EXPECT_EQ(blob_cylinder_field(apex + Vec3(0.0, 0.0, 1.0), base, apex, 1.0, 2.0).value, 0.0);
  EXPECT_EQ(blob_cylinder_field(Vec3(1.5, 0.0, 1.0), base, apex, 1.0, 2.0).value, 0.0);
}

TEST(BlobSphere, NegativeStrengthSubtracts) {
  const Vec3 c(0.0), p(0.3, 0.2, -0.1);
  const FieldSample plus = blob_sphere_field(p, c, 1.0, 2.0);
  const FieldSample minus = blob_sphere_field(p, c, 1.0, -2.0);
  EXPECT_EQ(minus.value, -plus.value);
  EXPECT_EQ(minus.gradient, -plus.gradient);
}

}  // namespace
}  // namespace convray::field
