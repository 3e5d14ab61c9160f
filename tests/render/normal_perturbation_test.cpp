// Bump normals: the tilt is the pattern's world-space gradient, tangential part only, scaled
// by the amount; checked on patterns whose gradient is known exactly.
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

TEST(NormalPerturbation, WrappedValuesDoNotMakeSpikes) {
  // Across x = 1 fract jumps from 1 to 0; the slope is still 1.
  expect_near(pattern_gradient(gradient_bumps(1.0).space, Vec3(1.0 - 1e-5, 0, 0)), Vec3(1, 0, 0),
              1e-6);
}

TEST(NormalPerturbation, GradientFollowsThePatternTransform) {
  scene::Normal normal = gradient_bumps(1.0);
  normal.space.transform = scene::Transform::scaling(Vec3(0.25, 1, 1));  // 4 ramps per unit
  expect_near(pattern_gradient(normal.space, Vec3(0.1, 0, 0)), Vec3(4, 0, 0), 1e-6);
  normal.space.transform = scene::Transform::rotation(Vec3(0, 90, 0));  // x turns to -z
  expect_near(pattern_gradient(normal.space, Vec3(0.2, 0.3, -0.4)), Vec3(0, 0, -1), 1e-6);
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
