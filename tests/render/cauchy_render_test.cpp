// A convolution object with `kernel cauchy` rendered whole: one point whose truncation box
// is smaller than its sphere F = T, so the solid is the box (a square in an orthographic
// view), where the quartic kernel's point is a ball (a disc): each image is checked pixel by
// pixel against the analytic outline, and they differ at the box's corners.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/world.hpp"
#include "render/render_scene.hpp"
#include "scene_records.hpp"

namespace convray::render {
namespace {

using namespace convray::testing;

constexpr int kPixels = 40;  // over 4 x 4 units: pixel centres at +-0.05, +-0.15, ...
constexpr double kSpan = 4.0;

Film render_point(const scene::ConvolutionObject& object) {
  scene::Scene scene;
  scene.camera = orthographic_camera(Vec3(0, 0, -10), kSpan, kSpan);
  scene::Implicit implicit;
  implicit.object = object;
  scene.objects.push_back(testing::object(implicit, glowing(rgb(1, 1, 1))));
  const geometry::World world(scene);
  RenderSettings settings;
  settings.width = kPixels;
  settings.height = kPixels;
  return render_scene(scene, world, settings).film;
}

Vec2 pixel_center(int i, int j) {
  const double step = kSpan / kPixels;
  return {-0.5 * kSpan + (i + 0.5) * step, 0.5 * kSpan - (j + 0.5) * step};
}

TEST(CauchyRender, TruncatedPointIsItsBoxWhereTheQuarticPointIsABall) {
  // Cauchy, s = 2, T = 0.2: 1/(1 + 4 r^2)^2 = T at r = 0.556; margin 0.33 cuts it to the
  // cube |x|, |y|, |z| <= 0.33 (whose corners, 0.57 away, are outside the ball: the solid is
  // cube and ball, whose outline along z is the full square, as its corners are 0.467 away).
  scene::ConvolutionObject cauchy;
  cauchy.kernel = {field::KernelType::cauchy, 2.0};
  cauchy.threshold = 0.2;
  cauchy.points.push_back({Vec3(0.0), {1.0, 0.33}});
  // Quartic, R = 1, T = 0.4: the ball of radius sqrt(1 - sqrt(0.4)) = 0.606.
  scene::ConvolutionObject quartic;
  quartic.threshold = 0.4;
  quartic.points.push_back({Vec3(0.0), {1.0, 1.0}});
  const Film square = render_point(cauchy), disc = render_point(quartic);
  const double ball = std::sqrt(1.0 - std::sqrt(0.4));
  int differ = 0;
  for (int j = 0; j < kPixels; ++j) {
    for (int i = 0; i < kPixels; ++i) {
      const Vec2 c = pixel_center(i, j);
      const bool in_square = std::abs(c.x) < 0.33 && std::abs(c.y) < 0.33;
      const bool in_disc = glm::length(c) < ball;
      EXPECT_EQ(square.at(i, j).r > 0.5, in_square) << i << ", " << j;
      EXPECT_EQ(disc.at(i, j).r > 0.5, in_disc) << i << ", " << j;
      differ += (square.at(i, j).r > 0.5) != (disc.at(i, j).r > 0.5);
    }
  }
  EXPECT_GT(differ, 40);
}

}  // namespace
}  // namespace convray::render
