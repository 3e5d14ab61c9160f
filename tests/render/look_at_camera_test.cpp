// The look_at camera (scene/look_at_camera.hpp, as `convray quick` sets it up, seen through
// render/scene_camera.hpp) reproduces POV-Ray's perspective camera: directions checked against
// vectors worked out by hand from POV-Ray's documented conventions; and quick's automatic
// framing and light (scene/quick_scene.hpp) show the whole object.
#include "scene/look_at_camera.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "render/scene_camera.hpp"
#include "scene/quick_scene.hpp"

namespace convray::render {
namespace {

constexpr double kTol = 1e-12;

using scene::default_light_position;
using scene::frame_bounds;
using scene::LookAtView;

// The camera record of a look_at view with the rays the renderer makes of it.
class Camera {
 public:
  explicit Camera(const LookAtView& view)
      : record_(scene::look_at_camera(view)), rays_(record_, view.width, view.height) {}
  const Vec3& location() const { return record_.location; }
  const Vec3& direction() const { return record_.direction; }
  const Vec3& right() const { return record_.right; }
  const Vec3& up() const { return record_.up; }
  const scene::Camera& record() const { return record_; }
  Ray ray_through(double x0, double y0) const { return rays_.ray_through(x0, y0); }
  Ray primary_ray(int i, int j) const { return rays_.primary_ray(i, j); }

 private:
  scene::Camera record_;
  SceneCamera rays_;
};

void expect_near(const Vec3& actual, const Vec3& expected, double tol = kTol) {
  EXPECT_NEAR(actual.x, expected.x, tol);
  EXPECT_NEAR(actual.y, expected.y, tol);
  EXPECT_NEAR(actual.z, expected.z, tol);
}

double degrees_between(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 /
         kPi;
}

TEST(LookAtCamera, CentrePixelLooksAtLookAt) {
  // Odd sizes put a pixel centre exactly on the image centre.
  const Camera camera({Vec3(3, -2, 7), Vec3(-1, 4, 2), 55.0, 31, 17});
  const Ray ray = camera.primary_ray(15, 8);
  expect_near(ray.origin, Vec3(3, -2, 7));
  expect_near(ray.direction, glm::normalize(Vec3(-1, 4, 2) - Vec3(3, -2, 7)));
}

TEST(LookAtCamera, PixelCentresOfASquareImageByHand) {
  // Angle 90, 2x2: right = <1,0,0>, up = <0,1,0>, direction length 0.5 / tan(45) = 0.5.
  // Pixel (0, 0) is the top-left one: x0 = -0.25, y0 = +0.25 -> <-0.25, 0.25, 0.5>.
  const Camera camera({Vec3(0), Vec3(0, 0, 1), 90.0, 2, 2});
  expect_near(camera.primary_ray(0, 0).direction, Vec3(-1, 1, 2) / std::sqrt(6.0));
  expect_near(camera.primary_ray(1, 0).direction, Vec3(1, 1, 2) / std::sqrt(6.0));
  expect_near(camera.primary_ray(1, 1).direction, Vec3(1, -1, 2) / std::sqrt(6.0));
}

TEST(LookAtCamera, AngleIsTheHorizontalFieldOfView) {
  for (const double angle : {10.0, 40.0, 90.0, 150.0}) {
    const Camera camera({Vec3(1, 2, 3), Vec3(4, 1, 9), angle, 800, 600});
    EXPECT_NEAR(degrees_between(camera.ray_through(-0.5, 0).direction,
                                camera.ray_through(0.5, 0).direction),
                angle, 1e-9);
    // Vertically the image plane spans 1 instead of 800/600.
    const double vertical =
        2.0 * std::atan(std::tan(angle * kPi / 360.0) * 600.0 / 800.0) * 180.0 / kPi;
    EXPECT_NEAR(degrees_between(camera.ray_through(0, -0.5).direction,
                                camera.ray_through(0, 0.5).direction),
                vertical, 1e-9);
  }
}

TEST(LookAtCamera, FrameVectorsHavePovRayLengths) {
  const Camera camera({Vec3(0, 0, -5), Vec3(0), 40.0, 160, 120});
  EXPECT_NEAR(glm::length(camera.right()), 160.0 / 120.0, kTol);
  EXPECT_NEAR(glm::length(camera.up()), 1.0, kTol);
  EXPECT_NEAR(glm::length(camera.direction()), 0.5 * (160.0 / 120.0) / std::tan(20.0 * kPi / 180.0),
              kTol);
}

TEST(LookAtCamera, LeftHandedFrameTurnedByLookAt) {
  // Looking along -x in left-handed coordinates (x right, y up, z forward), the viewer's
  // right is +z: the direction it faced before turning left.
  const Camera side({Vec3(5, 0, 0), Vec3(0), 60.0, 100, 100});
  expect_near(glm::normalize(side.right()), Vec3(0, 0, 1));
  expect_near(side.up(), Vec3(0, 1, 0));
  EXPECT_GT(side.primary_ray(99, 50).direction.z, 0.0);  // right edge leans to +z
  EXPECT_GT(side.primary_ray(50, 0).direction.y, 0.0);   // row 0 is at the top

  // From above and in front: up tilts away from the viewer, right stays horizontal.
  const Camera above({Vec3(0, 5, -5), Vec3(0), 60.0, 100, 100});
  expect_near(glm::normalize(above.right()), Vec3(1, 0, 0));
  expect_near(above.up(), Vec3(0, 1, 1) / std::sqrt(2.0));
}

TEST(LookAtCamera, RejectsDegenerateFrames) {
  EXPECT_THROW(Camera({Vec3(1), Vec3(1), 40.0, 8, 8}), std::invalid_argument);
  EXPECT_THROW(Camera({Vec3(0, 5, 0), Vec3(0), 40.0, 8, 8}),
               std::invalid_argument);  // straight down
  EXPECT_THROW(Camera({Vec3(0, 0, -1), Vec3(0), 0.0, 8, 8}), std::invalid_argument);
  EXPECT_THROW(Camera({Vec3(0, 0, -1), Vec3(0), 180.0, 8, 8}), std::invalid_argument);
  EXPECT_THROW(Camera({Vec3(0, 0, -1), Vec3(0), 40.0, 0, 8}), std::invalid_argument);
}

// Where p lands on the image plane, as (x0, y0) in [-0.5, 0.5] when in view.
Vec2 project(const Camera& camera, const Vec3& p) {
  const Vec3 v = p - camera.location();
  const double a =
      glm::dot(v, camera.direction()) / glm::dot(camera.direction(), camera.direction());
  const double b = glm::dot(v, camera.right()) / glm::dot(camera.right(), camera.right());
  const double c = glm::dot(v, camera.up()) / glm::dot(camera.up(), camera.up());
  return {b / a, c / a};
}

TEST(LookAtCamera, AutomaticFramingShowsTheWholeBoxFromTheFrontAndAbove) {
  const Box3 box{Vec3(-3, 10, 4), Vec3(5, 12, 30)};
  for (const auto& [w, h] : {std::pair{800, 600}, std::pair{300, 900}}) {
    const LookAtView spec = frame_bounds(box, w, h, 40.0);
    const Camera camera(spec);
    expect_near(spec.look_at, Vec3(1, 11, 17));
    EXPECT_LT(spec.location.z, box.lo.z);        // from the -z side
    EXPECT_GT(spec.location.y, spec.look_at.y);  // slightly above
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 p(corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                   corner & 4 ? box.hi.z : box.lo.z);
      const Vec2 q = project(camera, p);
      EXPECT_LE(std::abs(q.x), 0.5) << corner;
      EXPECT_LE(std::abs(q.y), 0.5) << corner;
    }
    // The bounding sphere fits within the narrower field of view, with a small margin only.
    const double radius = 0.5 * glm::length(box.extent());
    const double seen = std::asin(radius / glm::length(spec.location - spec.look_at));
    const double half_fov =
        std::atan(0.5 * std::min(1.0, double(w) / h) / glm::length(camera.direction()));
    EXPECT_LT(seen, half_fov);
    EXPECT_GT(seen, 0.9 * half_fov);
  }
}

TEST(LookAtCamera, DefaultLightIsAboveLeftAndBehindTheCamera) {
  const Box3 box{Vec3(-1), Vec3(1)};
  const Camera camera(frame_bounds(box, 800, 600, 40.0));
  const Vec3 offset = default_light_position(camera.record(), box) - camera.location();
  EXPECT_GT(glm::dot(offset, camera.up()), 0.0);
  EXPECT_LT(glm::dot(offset, camera.right()), 0.0);
  EXPECT_LT(glm::dot(offset, camera.direction()), 0.0);
  EXPECT_GT(glm::length(default_light_position(camera.record(), box)), 2.0 * std::sqrt(3.0));
}

}  // namespace
}  // namespace convray::render
