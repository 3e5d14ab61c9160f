// Our camera against POV-Ray's own pictures (tests/render/data/povray_sphere.pov, rendered by
// POV-Ray 3.7 without anti-aliasing): an off-centre sphere seen through a turned look_at
// camera must cover exactly the same pixels. This pins the frame (left-handed, look_at, the
// angle) and the sampling of pixel centres, which is what later pixel-for-pixel comparisons of
// blob scenes rest on.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geometry/world.hpp"
#include "render/render_scene.hpp"
#include "scene_records.hpp"
#include "reference/png_pixels.hpp"

namespace convray::render {
namespace {

struct Mask {
  int width = 0, height = 0;
  std::vector<bool> hit;
};

Mask povray_mask(const std::string& name) {
  const std::string path = std::string(CONVRAY_SOURCE_DIR) + "/tests/render/data/" + name;
  const reference::PngPixels pov = reference::read_png_rgb8(path);
  if (pov.rgb.empty()) {
    ADD_FAILURE() << pov.error;
    return {};
  }
  Mask mask{pov.width, pov.height, {}};
  // POV-Ray's sphere is white on black: red above the middle of its range marks a hit.
  for (size_t k = 0; k < pov.rgb.size(); k += 3) mask.hit.push_back(pov.rgb[k] > 127);
  return mask;
}

class PovRayCamera : public ::testing::TestWithParam<const char*> {};

TEST_P(PovRayCamera, SphereCoversTheSamePixelsAsPovRay) {
  const Mask pov = povray_mask(GetParam());
  ASSERT_GT(pov.width, 0);
  scene::Scene scene;
  scene.objects.push_back(
      testing::sphere(Vec3(0.7, 0.45, 0), 0.5, testing::glowing(testing::rgb(1, 1, 1))));
  scene.camera = testing::look_at_camera(Vec3(0.3, 0.4, -5), Vec3(0.1, 0.05, 0), 40.0, pov.width,
                                         pov.height);
  const geometry::World world(scene);
  RenderSettings settings;
  settings.width = pov.width;
  settings.height = pov.height;
  const Film film = render_scene(scene, world, settings).film;

  int differ = 0, hits = 0;
  for (int j = 0; j < pov.height; ++j) {
    for (int i = 0; i < pov.width; ++i) {
      const bool ours = film.at(i, j) != Vec3(0.0);
      hits += ours;
      differ += ours != pov.hit[size_t(j) * pov.width + i];
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_EQ(differ, 0);
}

INSTANTIATE_TEST_SUITE_P(Sizes, PovRayCamera,
                         ::testing::Values("povray_sphere_160x120.png",
                                           "povray_sphere_161x97.png"));

}  // namespace
}  // namespace convray::render
