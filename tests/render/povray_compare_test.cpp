// Whole pictures against POV-Ray 3.7's own: each scene is written here twice, as POV-Ray
// scene text and as the records our parser would make of it; the test runs the installed
// `povray` (skipped when there is none) and compares the two 8-bit sRGB images by PSNR.
// With CONVRAY_COMPARE_DIR set, both pictures are kept there (NAME.povray.png, NAME.convray.png).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "geometry/world.hpp"
#include "core/image_file.hpp"
#include "render/render_scene.hpp"
#include "scene_records.hpp"
#include "reference/png_pixels.hpp"

namespace convray::render {
namespace {

using namespace convray::testing;
namespace fs = std::filesystem;

constexpr int kWidth = 160, kHeight = 120;

bool povray_installed() { return std::system("povray --version > /dev/null 2>&1") == 0; }

// Renders `source` with POV-Ray into 8-bit RGB values (anti-aliased: +A0.3 +R3 without
// jitter); empty on failure.
std::vector<uint8_t> povray_render(const std::string& name, const std::string& source,
                                   bool antialias) {
  const fs::path folder =
      fs::temp_directory_path() / ("convray_povray_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const fs::path scene = folder / (name + ".pov"), image = folder / (name + ".png");
  std::ofstream(scene) << source;
  const std::string command = "povray +I" + scene.string() + " +O" + image.string() + " +W" +
                              std::to_string(kWidth) + " +H" + std::to_string(kHeight) +
                              (antialias ? " +A0.3 +R3 -J" : " -A") + " -D -GA > /dev/null 2>&1";
  if (std::system(command.c_str()) != 0) return {};
  const reference::PngPixels pixels = reference::read_png_rgb8(image.string());
  const bool read = pixels.width == kWidth && pixels.height == kHeight;
  if (const char* keep = std::getenv("CONVRAY_COMPARE_DIR")) {
    fs::copy_file(image, fs::path(keep) / (name + ".povray.png"),
                  fs::copy_options::overwrite_existing);
  }
  fs::remove_all(folder);
  return read ? pixels.rgb : std::vector<uint8_t>{};
}

// Our picture of the records, quantised as our PNG writer does (sRGB, rounded).
std::vector<uint8_t> convray_render(const std::string& name, const scene::Scene& scene,
                                    bool antialias) {
  const geometry::World world(scene);
  RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.antialias = antialias;
  const Film film = render_scene(scene, world, settings).film;
  if (const char* keep = std::getenv("CONVRAY_COMPARE_DIR")) {
    write_image_atomically((fs::path(keep) / (name + ".convray.png")).string(),
                           {kWidth, kHeight, film.rgb(), PixelEncoding::linear});
  }
  std::vector<uint8_t> pixels;
  for (float v : film.rgb()) pixels.push_back(uint8_t(std::lround(255.0f * encode_srgb(v))));
  return pixels;
}

double psnr(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  double sum = 0.0;
  for (size_t k = 0; k < a.size(); ++k) sum += (double(a[k]) - b[k]) * (double(a[k]) - b[k]);
  const double mse = sum / double(a.size());
  return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

const char* kHeader =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 2, -5> right x*160/120 angle 50 look_at <0, 0.6, 0> }\n";

scene::Scene records_with_camera() {
  scene::Scene scene;
  scene.camera = look_at_camera(Vec3(0, 2, -5), Vec3(0, 0.6, 0), 50, kWidth, kHeight);
  return scene;
}

std::shared_ptr<scene::Texture> checker_floor_texture() {
  auto floor = plain_texture(rgb(0, 0, 0), 0.1, 0.7);
  floor->pigment.space.pattern = scene::Pattern::checker;
  floor->pigment.block_colors = {rgb(0.9, 0.9, 0.9), rgb(0.2, 0.3, 0.5)};
  return floor;
}

struct Comparison {
  const char* name;
  std::string pov;
  std::function<scene::Scene()> records;
  double min_psnr;
  bool antialias = false;
};

Comparison phong_sphere_on_checker() {
  const std::string pov =
      std::string(kHeader) +
      "light_source { <-4, 6, -3> color rgb 1 }\n"
      "background { color rgb <0.1, 0.15, 0.3> }\n"
      "plane { y, 0 pigment { checker color rgb 0.9 color rgb <0.2, 0.3, 0.5> }\n"
      "  finish { ambient 0.1 diffuse 0.7 } }\n"
      "sphere { <0, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.1> }\n"
      "  finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 60 } }\n";
  auto records = [] {
    scene::Scene scene = records_with_camera();
    scene.lights.push_back(point_light(Vec3(-4, 6, -3)));
    scene.background = rgb(0.1, 0.15, 0.3);
    scene.objects.push_back(plane(Vec3(0, 1, 0), 0.0, checker_floor_texture()));
    auto ball = plain_texture(rgb(0.8, 0.2, 0.1), 0.1, 0.7);
    ball->finish.phong = 0.8;
    ball->finish.phong_size = 60;
    scene.objects.push_back(sphere(Vec3(0, 1, 0), 1.0, ball));
    return scene;
  };
  return {"phong_sphere_on_checker", pov, records, 40.0};
}

Comparison glass_mirror_spotlight() {
  const std::string pov =
      std::string(kHeader) +
      "light_source { <3, 6, -4> color rgb <1, 0.9, 0.8> spotlight point_at <0, 0, 0>\n"
      "  radius 20 falloff 35 tightness 5 }\n"
      "light_source { <-5, 4, -6> color rgb 0.4 }\n"
      "background { color rgb <0.05, 0.05, 0.1> }\n"
      "plane { y, 0 pigment { checker color rgb 0.9 color rgb <0.2, 0.3, 0.5> }\n"
      "  finish { ambient 0.1 diffuse 0.7 } }\n"
      "sphere { <-0.9, 0.8, 0>, 0.8 pigment { color rgb 1 filter 0.3 transmit 0.6 }\n"
      "  finish { ambient 0 diffuse 0.1 specular 0.6 roughness 0.02 } interior { ior 1.5 } }\n"
      "sphere { <0.9, 0.8, 0.5>, 0.8 pigment { color rgb <0.7, 0.7, 0.2> }\n"
      "  finish { ambient 0.05 diffuse 0.3 reflection 0.6 phong 0.5 metallic } }\n";
  auto records = [] {
    scene::Scene scene = records_with_camera();
    scene::Light spot = point_light(Vec3(3, 6, -4), Vec3(1, 0.9, 0.8));
    spot.kind = scene::Light::Kind::spotlight;
    spot.point_at = Vec3(0);
    spot.radius = 20;
    spot.falloff = 35;
    spot.tightness = 5;
    scene.lights.push_back(spot);
    scene.lights.push_back(point_light(Vec3(-5, 4, -6), Vec3(0.4)));
    scene.background = rgb(0.05, 0.05, 0.1);
    scene.objects.push_back(plane(Vec3(0, 1, 0), 0.0, checker_floor_texture()));
    auto glass = plain_texture(rgb(1, 1, 1, 0.3, 0.6), 0.0, 0.1);
    glass->finish.specular = 0.6;
    glass->finish.roughness = 0.02;
    scene.objects.push_back(sphere(Vec3(-0.9, 0.8, 0), 0.8, glass, scene::Interior{1.5}));
    auto chrome = plain_texture(rgb(0.7, 0.7, 0.2), 0.05, 0.3);
    chrome->finish.reflection = Vec3(0.6);
    chrome->finish.phong = 0.5;
    chrome->finish.metallic = 1.0;
    scene.objects.push_back(sphere(Vec3(0.9, 0.8, 0.5), 0.8, chrome));
    return scene;
  };
  return {"glass_mirror_spotlight", pov, records, 35.0};
}

Comparison fog_gradient_onion() {
  const std::string pov =
      std::string(kHeader) +
      "light_source { <2, 5, -6> color rgb 1 fade_distance 4 fade_power 2 }\n"
      "background { color rgb <0.3, 0.3, 0.35> }\n"
      "fog { distance 12 color rgb <0.5, 0.55, 0.6> }\n"
      "plane { y, 0 pigment { onion color_map { [0 rgb <0.1, 0.4, 0.1>] [1 rgb 0.9] } }\n"
      "  finish { ambient 0.15 diffuse 0.6 } }\n"
      "box { <-1, 0, -0.5>, <1, 1.5, 0.5> pigment { gradient y\n"
      "  color_map { [0 rgb <1, 0, 0>] [0.5 rgb <1, 1, 0>] [1 rgb <0, 0, 1>] } scale 0.5 }\n"
      "  finish { ambient 0.1 diffuse 0.8 brilliance 2 } rotate y*30 }\n";
  auto records = [] {
    scene::Scene scene = records_with_camera();
    scene::Light light = point_light(Vec3(2, 5, -6));
    light.fade_distance = 4;
    light.fade_power = 2;
    scene.lights.push_back(light);
    scene.background = rgb(0.3, 0.3, 0.35);
    scene::Fog fog;
    fog.distance = 12;
    fog.color = rgb(0.5, 0.55, 0.6);
    scene.fogs.push_back(fog);
    auto floor = plain_texture(rgb(0, 0, 0), 0.15, 0.6);
    floor->pigment.space.pattern = scene::Pattern::onion;
    floor->pigment.color_map = {{0.0, rgb(0.1, 0.4, 0.1)}, {1.0, rgb(0.9, 0.9, 0.9)}};
    scene.objects.push_back(plane(Vec3(0, 1, 0), 0.0, floor));
    auto bands = plain_texture(rgb(0, 0, 0), 0.1, 0.8);
    bands->finish.brilliance = 2;
    bands->pigment.space.pattern = scene::Pattern::gradient;
    bands->pigment.space.gradient_axis = Vec3(0, 1, 0);
    // The object's rotation applies to its texture too (the parser appends it).
    const scene::Transform turn = scene::Transform::rotation(Vec3(0, 30, 0));
    bands->pigment.space.transform = scene::Transform::scaling(Vec3(0.5)).then(turn);
    bands->pigment.color_map = {{0.0, rgb(1, 0, 0)}, {0.5, rgb(1, 1, 0)}, {1.0, rgb(0, 0, 1)}};
    scene.objects.push_back(
        object(scene::Box{Vec3(-1, 0, -0.5), Vec3(1, 1.5, 0.5)}, bands, std::nullopt, turn));
    return scene;
  };
  return {"fog_gradient_onion", pov, records, 40.0};
}

Comparison ground_fog_and_sky_sphere() {
  const std::string pov =
      std::string(kHeader) +
      "light_source { <-4, 6, -3> color rgb 1 }\n"
      "sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.6, 0.3>] [0.5 rgb <0.2, 0.3, "
      "0.8>] } }\n"
      "  pigment { gradient x color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 1, 1, 0.5>] [1 rgbt "
      "1] } scale 0.1 }\n"
      "  rotate y*20 }\n"
      "fog { fog_type 2 distance 3 fog_offset 0.3 fog_alt 0.4 color rgb <0.7, 0.75, 0.8> }\n"
      "fog { distance 30 color rgbft <0.6, 0.3, 0.2, 0.2, 0.5> }\n"
      "plane { y, 0 pigment { checker color rgb 0.9 color rgb <0.2, 0.3, 0.5> }\n"
      "  finish { ambient 0.1 diffuse 0.7 } }\n"
      "sphere { <0, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.1> }\n"
      "  finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 60 } }\n";
  auto records = [] {
    scene::Scene scene = phong_sphere_on_checker().records();
    scene.background = rgb(0, 0, 0);
    scene::SkySphere sky;
    scene::Pigment horizon;
    horizon.space.pattern = scene::Pattern::gradient;
    horizon.space.gradient_axis = Vec3(0, 1, 0);
    horizon.color_map = {{0.0, rgb(0.9, 0.6, 0.3)}, {0.5, rgb(0.2, 0.3, 0.8)}};
    scene::Pigment stripes;
    stripes.space.pattern = scene::Pattern::gradient;
    stripes.space.transform = scene::Transform::scaling(Vec3(0.1));
    stripes.color_map = {
        {0.0, rgb(1, 1, 1, 0, 1)}, {0.5, rgb(1, 1, 1, 0, 0.5)}, {1.0, rgb(1, 1, 1, 0, 1)}};
    sky.pigments = {horizon, stripes};
    sky.transform = scene::Transform::rotation(Vec3(0, 20, 0));
    scene.sky_sphere = sky;
    scene::Fog ground;
    ground.kind = scene::Fog::Kind::ground;
    ground.distance = 3;
    ground.offset = 0.3;
    ground.altitude = 0.4;
    ground.color = rgb(0.7, 0.75, 0.8);
    scene::Fog haze;
    haze.distance = 30;
    haze.color = rgb(0.6, 0.3, 0.2, 0.2, 0.5);
    scene.fogs = {ground, haze};
    return scene;
  };
  return {"ground_fog_and_sky_sphere", pov, records, 40.0};
}

// A pattern used as a normal (POV-Ray's slope factor, normal_perturbation.hpp), scaled and
// turned with its object.
Comparison marble_normal() {
  const std::string pov = std::string(kHeader) +
                          "light_source { <-4, 6, -3> color rgb 1 }\n"
                          "background { color rgb <0.1, 0.15, 0.3> }\n"
                          "sphere { <0, 1, 0>, 1 pigment { color rgb <0.8, 0.6, 0.2> }\n"
                          "  normal { marble 1.5 scale 0.3 rotate z*40 }\n"
                          "  finish { ambient 0.1 diffuse 0.7 phong 0.6 } }\n";
  auto records = [] {
    scene::Scene scene = records_with_camera();
    scene.lights.push_back(point_light(Vec3(-4, 6, -3)));
    scene.background = rgb(0.1, 0.15, 0.3);
    auto texture = plain_texture(rgb(0.8, 0.6, 0.2), 0.1, 0.7);
    texture->finish.phong = 0.6;
    texture->normal.space.pattern = scene::Pattern::marble;
    texture->normal.space.transform =
        scene::Transform::scaling(Vec3(0.3)).then(scene::Transform::rotation(Vec3(0, 0, 40)));
    texture->normal.amount = 1.5;
    scene.objects.push_back(sphere(Vec3(0, 1, 0), 1.0, texture));
    return scene;
  };
  return {"marble_normal", pov, records, 40.0};
}

// A 5 x 5 area light, sampled adaptively as POV-Ray does (area_light.hpp).
Comparison area_light_penumbra(int adaptive) {
  const std::string pov =
      std::string(kHeader) +
      "light_source { <-3, 5, -2> color rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 adaptive " +
      std::to_string(adaptive) +
      " }\n"
      "background { color rgb <0.1, 0.15, 0.3> }\n"
      "plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0.1 diffuse 0.7 } }\n"
      "sphere { <0, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.1> }\n"
      "  finish { ambient 0.1 diffuse 0.7 } }\n";
  auto records = [adaptive] {
    scene::Scene scene = records_with_camera();
    scene::Light light = point_light(Vec3(-3, 5, -2));
    scene::AreaLight area;
    area.axis1 = Vec3(2, 0, 0);
    area.axis2 = Vec3(0, 0, 2);
    area.size1 = area.size2 = 5;
    area.adaptive = adaptive;
    light.area = area;
    scene.lights.push_back(light);
    scene.background = rgb(0.1, 0.15, 0.3);
    scene.objects.push_back(plane(Vec3(0, 1, 0), 0.0, plain_texture(rgb(0.8, 0.8, 0.8), 0.1, 0.7)));
    scene.objects.push_back(
        sphere(Vec3(0, 1, 0), 1.0, plain_texture(rgb(0.8, 0.2, 0.1), 0.1, 0.7)));
    return scene;
  };
  return {adaptive == 0 ? "area_light_adaptive_0" : "area_light_adaptive_2", pov, records, 40.0};
}

Comparison area_light_adaptive_0() { return area_light_penumbra(0); }
Comparison area_light_adaptive_2() { return area_light_penumbra(2); }

// Anti-aliased (+A0.3 +R3 -J): the same samples where both supersample, but POV-Ray decides
// pixel by pixel in its own order (a neighbour already supersampled compares by its new
// value), so the decisions differ where the checker recedes to sub-pixel squares; 43 dB.
Comparison antialiased_phong_sphere_on_checker() {
  Comparison comparison = phong_sphere_on_checker();
  comparison.name = "antialiased_phong_sphere_on_checker";
  comparison.antialias = true;
  return comparison;
}

// A shadowless fill light lights diffusely but casts no shadow and, in POV-Ray 3.7, makes no
// phong or specular highlight.
Comparison shadowless_fill_light() {
  const std::string pov =
      std::string(kHeader) +
      "light_source { <-4, 6, -3> color rgb 0.7 }\n"
      "light_source { <5, 3, -6> color rgb 0.6 shadowless }\n"
      "background { color rgb <0.1, 0.15, 0.3> }\n"
      "plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0.1 diffuse 0.7 } }\n"
      "sphere { <0, 1, 0>, 1 pigment { color rgb <0.2, 0.7, 0.4> }\n"
      "  finish { ambient 0.1 diffuse 0.7 phong 0.9 phong_size 40 specular 0.4 } }\n";
  auto records = [] {
    scene::Scene scene = records_with_camera();
    scene::Light key = point_light(Vec3(-4, 6, -3));
    key.color = rgb(0.7, 0.7, 0.7);
    scene::Light fill = point_light(Vec3(5, 3, -6));
    fill.color = rgb(0.6, 0.6, 0.6);
    fill.shadowless = true;
    scene.lights = {key, fill};
    scene.background = rgb(0.1, 0.15, 0.3);
    scene.objects.push_back(plane(Vec3(0, 1, 0), 0.0, plain_texture(rgb(0.8, 0.8, 0.8), 0.1, 0.7)));
    auto ball = plain_texture(rgb(0.2, 0.7, 0.4), 0.1, 0.7);
    ball->finish.phong = 0.9;
    ball->finish.phong_size = 40;
    ball->finish.specular = 0.4;
    scene.objects.push_back(sphere(Vec3(0, 1, 0), 1.0, ball));
    return scene;
  };
  return {"shadowless_fill_light", pov, records, 40.0};
}

class AgainstPovRay : public ::testing::TestWithParam<Comparison (*)()> {};

TEST_P(AgainstPovRay, PictureMatchesPovRay) {
  if (!povray_installed()) GTEST_SKIP() << "povray is not installed";
  const Comparison comparison = GetParam()();
  const std::vector<uint8_t> theirs =
      povray_render(comparison.name, comparison.pov, comparison.antialias);
  ASSERT_FALSE(theirs.empty()) << "povray failed on " << comparison.name;
  const std::vector<uint8_t> ours =
      convray_render(comparison.name, comparison.records(), comparison.antialias);
  ASSERT_EQ(ours.size(), theirs.size());
  const double db = psnr(ours, theirs);
  std::cout << comparison.name << ": PSNR " << db << " dB\n";
  EXPECT_GE(db, comparison.min_psnr) << comparison.name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, AgainstPovRay,
                         ::testing::Values(&phong_sphere_on_checker, &glass_mirror_spotlight,
                                           &fog_gradient_onion, &ground_fog_and_sky_sphere,
                                           &area_light_adaptive_0, &area_light_adaptive_2,
                                           &marble_normal, &antialiased_phong_sphere_on_checker,
                                           &shadowless_fill_light));

}  // namespace
}  // namespace convray::render
