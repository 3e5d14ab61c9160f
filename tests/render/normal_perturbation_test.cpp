// Bump normals: POV-Ray's tilt of a linear ramp (2/15 of the amount per unit slope, measured
// with the povray binary), its crease where the ramp wraps, and its turn with the pattern.
// Whole pictures against the binary's: tests/app/povray_sampled_normal_test.cpp.
#include "render/normal_perturbation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace convray::render {
namespace {

void expect_near(const Vec3& actual, const Vec3& expected, double tol) {
  EXPECT_NEAR(actual.x, expected.x, tol);
  EXPECT_NEAR(actual.y, expected.y, tol);
  EXPECT_NEAR(actual.z, expected.z, tol);
}

scene::Normal gradient_bumps(double amount) {
  scene::Normal normal;
  normal.space.pattern = scene::Pattern::gradient;  // value fract(x): gradient <1, 0, 0>
  normal.amount = amount;
  return normal;
}

TEST(NormalPerturbation, NoPatternOrNoAmountLeavesTheNormal) {
  const Vec3 n = glm::normalize(Vec3(1, 2, 3));
  expect_near(perturb_normal(scene::Normal{}, Vec3(0.3), n), n, 0.0);
  expect_near(perturb_normal(gradient_bumps(0.0), Vec3(0.3), n), n, 0.0);
}

TEST(NormalPerturbation, TiltsAgainstTheTangentialGradientLikePovRay) {
  // On a floor (normal +y) the gradient <1,0,0> is all tangential: n' = normalize(-k a, 1, 0)
  // with POV-Ray's k = 2/15 (its `normal { gradient x 3 }` tilts by -0.39999).
  expect_near(perturb_normal(gradient_bumps(3.0), Vec3(0.3, 0, 0.7), Vec3(0, 1, 0)),
              glm::normalize(Vec3(-0.4, 1, 0)), 1e-8);
  // Facing +x the gradient is along the normal: no tilt.
  expect_near(perturb_normal(gradient_bumps(0.5), Vec3(0.3, 0, 0.7), Vec3(1, 0, 0)), Vec3(1, 0, 0),
              1e-8);
}

TEST(NormalPerturbation, AWrappingRampCreasesWithinTheAccuracy) {
  // POV-Ray samples a tetrahedron of circumradius `accuracy` (0.02): beyond it from x = 0,
  // where fract(x) wraps, the ramp tilts as everywhere; within it the jump of 1 tilts far more.
  const Vec3 up(0, 1, 0);
  const Vec3 plain = perturb_normal(gradient_bumps(1.0), Vec3(0.5, 0, 0.7), up);
  expect_near(perturb_normal(gradient_bumps(1.0), Vec3(0.03, 0, 0.7), up), plain, 1e-12);
  expect_near(perturb_normal(gradient_bumps(1.0), Vec3(-0.03, 0, 0.7), up), plain, 1e-12);
  EXPECT_LT(perturb_normal(gradient_bumps(1.0), Vec3(0.005, 0, 0.7), up).y, 0.8);
}

TEST(NormalPerturbation, ScalingThePatternKeepsTheTiltsSteepness) {
  scene::Normal normal = gradient_bumps(3.0);
  normal.space.transform = scene::Transform::scaling(Vec3(0.025));
  expect_near(perturb_normal(normal, Vec3(0.01, 0, 0.7), Vec3(0, 1, 0)),
              glm::normalize(Vec3(-0.4, 1, 0)), 1e-6);
}

TEST(NormalPerturbation, BumpsGiveUnitNormalsOnTheViewersSide) {
  scene::Normal bumps;
  bumps.space.pattern = scene::Pattern::bumps;
  bumps.amount = 0.8;
  int tilted = 0;
  for (int k = 0; k < 100; ++k) {
    const Vec3 p(0.13 * k, 0.7, -0.29 * k);
    const Vec3 n = perturb_normal(bumps, p, Vec3(0, 1, 0));
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    EXPECT_GT(n.y, 0.0);
    tilted += n.y < 0.999;
  }
  EXPECT_GT(tilted, 50);
}

}  // namespace
}  // namespace convray::render
