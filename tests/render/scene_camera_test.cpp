// The render camera built from the scene's frame vectors: perspective rays through the pixel
// centres, orthographic rays parallel.
#include "render/scene_camera.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace convray::render {
namespace {


void expect_near(const Vec3& actual, const Vec3& expected, double tol = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tol);
  EXPECT_NEAR(actual.y, expected.y, tol);
  EXPECT_NEAR(actual.z, expected.z, tol);
}

TEST(SceneCamera, PixelCentresByHand) {
  scene::Camera record;  // POV-Ray's default: at the origin looking along +z
  record.right = Vec3(2, 0, 0);
  const SceneCamera camera(record, 4, 2);
  // Pixel (0, 0): x0 = 0.5/4 - 0.5 = -0.375, y0 = 0.5 - 0.5/2 = 0.25.
  expect_near(camera.primary_ray(0, 0).direction, glm::normalize(Vec3(-0.75, 0.25, 1)));
  expect_near(camera.primary_ray(3, 1).direction, glm::normalize(Vec3(0.75, -0.25, 1)));
}

TEST(SceneCamera, OrthographicRaysAreParallelFromTheImagePlane) {
  scene::Camera record;
  record.kind = scene::Camera::Kind::orthographic;
  record.location = Vec3(0, 0, -10);
  record.direction = Vec3(0, 0, 3);
  record.right = Vec3(4, 0, 0);
  record.up = Vec3(0, 3, 0);
  const SceneCamera camera(record, 40, 30);
  const Ray corner = camera.primary_ray(0, 0);
  expect_near(corner.direction, Vec3(0, 0, 1));
  // POV-Ray's orthographic pixel centre, verified on its renders: (-1.95, 1.45).
  expect_near(corner.origin, Vec3(-1.95, 1.45, -10));
  expect_near(camera.primary_ray(39, 29).origin, Vec3(1.95, -1.45, -10));
}

TEST(SceneCamera, RejectsDegenerateFrames) {
  scene::Camera record;
  EXPECT_THROW(SceneCamera(record, 0, 10), std::invalid_argument);
  record.direction = Vec3(0);
  EXPECT_THROW(SceneCamera(record, 10, 10), std::invalid_argument);
  record.direction = Vec3(0, 0, 1);
  record.up = Vec3(2, 0, 0);  // parallel to right
  EXPECT_THROW(SceneCamera(record, 10, 10), std::invalid_argument);
}

}  // namespace
}  // namespace convray::render
