// The camera's final frame, against vectors derived by hand from POV-Ray 3.7's documented
// rules (angle sets |direction| = 0.5 |right| / tan(angle/2); look_at turns direction, right
// = unit(sky x direction), up = direction x right, keeping lengths and handedness; then the
// transforms) and, for the orthographic angle, from POV-Ray renders.
#include <cmath>

#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;

scene::Camera camera_of(const std::string& text) { return parse(text).scene.camera; }

double degrees_to_radians(double degrees) { return degrees * kPi / 180.0; }

TEST(ItemsCamera, DefaultsArePovRays) {
  for (const scene::Camera& camera : {parse("").scene.camera, camera_of("camera { }")}) {
    EXPECT_EQ(camera.kind, scene::Camera::Kind::perspective);
    expect_near(camera.location, Vec3(0.0));
    expect_near(camera.direction, Vec3(0, 0, 1));
    expect_near(camera.right, Vec3(1.33, 0, 0));
    expect_near(camera.up, Vec3(0, 1, 0));
  }
}

TEST(ItemsCamera, LookAtStraightAheadKeepsTheDefaultFrame) {
  const auto camera = camera_of("camera { location <0, 0, -5> look_at 0 }");
  expect_near(camera.location, Vec3(0, 0, -5));
  expect_near(camera.direction, Vec3(0, 0, 1));
  expect_near(camera.right, Vec3(1.33, 0, 0));
  expect_near(camera.up, Vec3(0, 1, 0));
}

TEST(ItemsCamera, LookAtTurnsTheFrameKeepingLengths) {
  // Looking along (1, 0, 1)/sqrt2: right = unit(y x d) = (1, 0, -1)/sqrt2, up = d x right = y.
  const auto camera = camera_of("camera { location <0, 0, -5> look_at <5, 0, 0> }");
  const double h = std::sqrt(0.5);
  expect_near(camera.direction, Vec3(h, 0, h));
  expect_near(camera.right, 1.33 * Vec3(h, 0, -h));
  expect_near(camera.up, Vec3(0, 1, 0));
}

TEST(ItemsCamera, LookingDownTiltsUp) {
  // From <0, 3, -4> to the origin: d = (0, -3, 4)/5, right = unit(y x d) = x,
  // up = d x x = (0, 4, 3)/5.
  const auto camera = camera_of("camera { location <0, 3, -4> look_at 0 right x up y }");
  expect_near(camera.direction, Vec3(0, -0.6, 0.8));
  expect_near(camera.right, Vec3(1, 0, 0));
  expect_near(camera.up, Vec3(0, 0.8, 0.6));
}

TEST(ItemsCamera, AngleSetsTheDirectionLength) {
  const auto camera = camera_of("camera { location <0,0,-5> right x*4/3 angle 90 look_at 0 }");
  // 0.5 * (4/3) / tan(45 degrees) = 2/3.
  expect_near(camera.direction, Vec3(0, 0, 2.0 / 3.0), 1e-12);
  expect_near(camera.right, Vec3(4.0 / 3.0, 0, 0));
}

TEST(ItemsCamera, SameFrameAsTheRendererForItsPovRayReference) {
  // tests/render/data/povray_sphere.pov at 160x120: render/camera.cpp reproduces POV-Ray's
  // frame for right <W/H, 0, 0>, up y, angle 40; the scene must give the same vectors.
  ParseOptions options;
  options.image_width = 160;
  options.image_height = 120;
  const auto result = parse_string(R"(
    camera { perspective location <0.3, 0.4, -5> right x * image_width / image_height up y
             angle 40 look_at <0.1, 0.05, 0> })",
                                   "camera.pov", options);
  const scene::Camera& camera = result.scene.camera;
  const Vec3 location(0.3, 0.4, -5), look_at(0.1, 0.05, 0), sky(0, 1, 0);
  const double right_length = 160.0 / 120.0;
  const Vec3 forward = glm::normalize(look_at - location);
  const Vec3 right = glm::normalize(glm::cross(sky, forward)) * right_length;
  const Vec3 up = glm::normalize(glm::cross(forward, right));
  const double length = 0.5 * right_length / std::tan(degrees_to_radians(20.0));
  expect_near(camera.location, location);
  expect_near(camera.direction, forward * length, 1e-12);
  expect_near(camera.right, right, 1e-12);
  expect_near(camera.up, up, 1e-12);
}

TEST(ItemsCamera, SkyTiltsTheFrame) {
  // Looking along z with sky <1, 1, 0>: right = unit(sky x z) = (1, -1, 0)/sqrt2,
  // up = z x right = (1, 1, 0)/sqrt2.
  const auto camera = camera_of("camera { sky <1, 1, 0> look_at <0, 0, 1> right x }");
  const double h = std::sqrt(0.5);
  expect_near(camera.right, Vec3(h, -h, 0));
  expect_near(camera.up, Vec3(h, h, 0));
}

TEST(ItemsCamera, RightHandedRightStaysOnItsSide) {
  const auto camera = camera_of("camera { location <0, 0, -5> right -1.33*x look_at 0 }");
  expect_near(camera.right, Vec3(-1.33, 0, 0));
  expect_near(camera.up, Vec3(0, 1, 0));
}

TEST(ItemsCamera, ItemsMayComeInAnyOrder) {
  const auto a = camera_of("camera { look_at <1, 2, 3> angle 50 location <-2, 1, -6> }");
  const auto b = camera_of("camera { location <-2, 1, -6> angle 50 look_at <1, 2, 3> }");
  expect_near(a.direction, b.direction);
  expect_near(a.right, b.right);
  expect_near(a.up, b.up);
}

TEST(ItemsCamera, TransformsComeLast) {
  const auto camera = camera_of("camera { location <0, 0, -5> look_at 0 rotate 90*y }");
  expect_near(camera.location, Vec3(-5, 0, 0));
  expect_near(camera.direction, Vec3(1, 0, 0));
  expect_near(camera.right, Vec3(0, 0, -1.33));
  expect_near(camera.up, Vec3(0, 1, 0));
}

TEST(ItemsCamera, OrthographicWithoutAngleKeepsRightAndUp) {
  const auto camera =
      camera_of("camera { orthographic location <0, 0, -10> right 4*x up 3*y look_at 0 }");
  EXPECT_EQ(camera.kind, scene::Camera::Kind::orthographic);
  expect_near(camera.right, Vec3(4, 0, 0));
  expect_near(camera.up, Vec3(0, 3, 0));
}

TEST(ItemsCamera, OrthographicAngleSizesThePlaneAtTheLookAtDistance) {
  // Measured with POV-Ray 3.7: the plane is 2 d tan(angle/2) wide at the distance d from
  // location to look_at (up scaled by the same factor); look_at defaults to <0, 0, 1>.
  const double width = 2.0 * 10.0 * std::tan(degrees_to_radians(30.0));
  const auto camera =
      camera_of("camera { orthographic location <0, 0, -10> right x up 0.5*y angle 60 look_at 0 }");
  expect_near(camera.right, Vec3(width, 0, 0), 1e-12);
  expect_near(camera.up, Vec3(0, 0.5 * width, 0), 1e-12);
  const auto no_look_at =
      camera_of("camera { orthographic location <0, 0, -10> right x up y angle 60 }");
  expect_near(no_look_at.right, Vec3(1.1 * width, 0, 0), 1e-12);
}

TEST(ItemsCamera, DeclaredCameraCanBeMoved) {
  const auto camera = camera_of(
      "#declare C = camera { location <0, 0, -5> look_at 0 }\ncamera { C translate <1, 0, 0> }");
  expect_near(camera.location, Vec3(1, 0, -5));
  expect_near(camera.direction, Vec3(0, 0, 1));
}

TEST(ItemsCamera, LookingAlongTheSkyKeepsTheGivenRightVector) {
  // Rendered with POV-Ray 3.7 (a gradient on the ground seen from 6*y): it warns and keeps
  // the right vector as given; up = direction x right then points along +z.
  const auto result = parse("camera { location 6*y look_at 0 }");
  const scene::Camera& camera = result.scene.camera;
  expect_near(camera.direction, Vec3(0, -1, 0));
  expect_near(camera.right, Vec3(1.33, 0, 0));
  expect_near(camera.up, Vec3(0, 0, 1));
  EXPECT_TRUE(has_warning(result, "camera looks along its sky vector"));
}

TEST(ItemsCamera, Errors) {
  EXPECT_TRUE(fails_with("camera { angle 180 }", 1, 10, "strictly between 0 and 180"));
  EXPECT_TRUE(
      fails_with("camera { location 1 look_at 1 }", 1, 21, "look_at is the camera's location"));
  EXPECT_TRUE(fails_with("camera { omnimax }", 1, 10, "not supported yet"));
  EXPECT_TRUE(fails_with("camera { cylinder 5 }", 1, 19, "must be 1, 2, 3 or 4"));
  EXPECT_TRUE(fails_with("camera { loaction 0 }", 1, 10, "did you mean 'location'?"));
  EXPECT_TRUE(fails_with("camera { location 0 direction 0 }", 1, 1,
                         "camera direction, right and up must not be 0"));
}

}  // namespace
}  // namespace convray::sdl
