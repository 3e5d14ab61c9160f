// convray view's work without a window (src/app/view_session.hpp, view_camera.hpp,
// view_edits.hpp, view_worker.hpp, file_watch.hpp). Every expectation is checked against
// something the view code did not make: the plain renderer on a scene file written out with
// the printed text, the scene parser's own records, the full-resolution render's pixels.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <unistd.h>

#include "app/file_watch.hpp"
#include "app/view_camera.hpp"
#include "app/view_edits.hpp"
#include "app/view_session.hpp"
#include "app/view_worker.hpp"
#include "app/geometry_object_queries.hpp"
#include "core/image_file.hpp"
#include "core/png_writer.hpp"
#include "display/preview_image.hpp"
#include "render/function_sources.hpp"
#include "render/render_scene.hpp"
#include "sdl/parser.hpp"
#include "reference/png_pixels.hpp"

namespace convray::app {
namespace {

namespace fs = std::filesystem;

const std::string kScenes = std::string(CONVRAY_SOURCE_DIR) + "/scenes";
const std::string kSoup = kScenes + "/soup.pov";
constexpr int kW = 100, kH = 76;  // not multiples of 8: the last blocks are cut short

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

ViewOptions soup_options() {
  ViewOptions o;
  o.input = kSoup;
  o.width = kW;
  o.height = kH;
  return o;
}

// The picture of scene text `text` (its meshes found in scenes/) by the plain renderer.
std::vector<float> render_text(const std::string& text) {
  sdl::ParseOptions p;
  p.image_width = kW;
  p.image_height = kH;
  p.library_paths = {kScenes};
  p.read_folders = {kScenes};
  p.object_queries = geometry_object_queries();
  p.color_sources = render::renderer_color_sources();
  const sdl::ParseResult parsed = sdl::parse_string(text, kScenes + "/edited.pov", p);
  const geometry::World world(parsed.scene);
  render::RenderSettings s;
  s.width = kW;
  s.height = kH;
  const render::RenderResult r = render::render_scene(parsed.scene, world, s);
  return {r.film.rgb().begin(), r.film.rgb().end()};
}

std::vector<float> pixels(const render::RenderResult& r) {
  return {r.film.rgb().begin(), r.film.rgb().end()};
}

// soup.pov with its camera { } replaced by `camera`.
std::string with_camera_text(const std::string& camera) {
  std::string text = read_text(kSoup);
  const size_t begin = text.find("camera {");
  const size_t end = text.find("}\n", begin) + 2;
  return text.replace(begin, end - begin, camera);
}

TEST(ViewSession, CoarsePixelsAreTheFullRendersPixelsAtTheBlocksSamples) {
  ViewSession session(soup_options());
  const auto frame = session.load({});
  const render::RenderResult full = session.render(*frame, 1);
  const render::RenderResult coarse = session.render(*frame, kCoarseBlock);
  int checked = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const int bx = x / 8 * 8, by = y / 8 * 8;
      const int sx = std::min(bx + 4, std::min(bx + 8, kW) - 1);
      const int sy = std::min(by + 4, std::min(by + 8, kH) - 1);
      ASSERT_EQ(coarse.film.at(x, y), full.film.at(sx, sy)) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_EQ(checked, kW * kH);
  EXPECT_EQ(coarse.stats.camera_rays, uint64_t((kW + 7) / 8 * ((kH + 7) / 8)));
}

TEST(ViewSession, TheFullPictureIsTheFileRender) {
  ViewSession session(soup_options());
  const auto frame = session.load({});
  EXPECT_EQ(pixels(session.render(*frame, 1)), render_text(read_text(kSoup)));
}

TEST(ViewCamera, TheSceneCamerasBlockParsesToTheSameCamera) {
  ViewSession session(soup_options());
  const auto frame = session.load({});
  const scene::Camera& scene = frame->scene.camera;
  sdl::ParseOptions p;
  const scene::Camera printed =
      sdl::parse_string(camera_block(frame->camera), "block.pov", p).scene.camera;
  EXPECT_EQ(printed.location, scene.location);
  EXPECT_EQ(printed.direction, scene.direction);
  EXPECT_EQ(printed.right, scene.right);
  EXPECT_EQ(printed.up, scene.up);
}

TEST(ViewCamera, AMovedViewsPrintedBlockRendersTheSamePicture) {
  ViewSession session(soup_options());
  const auto scene_frame = session.load({});
  ViewOverrides moved;
  moved.camera = pan(zoom(orbit(scene_frame->camera, 0.4, 0.25), 0.8), 0.05, -0.03);
  const auto frame = session.load(moved);
  EXPECT_NE(frame->scene.camera.location, scene_frame->scene.camera.location);
  const std::vector<float> view = pixels(session.render(*frame, 1));
  EXPECT_NE(view, pixels(session.render(*scene_frame, 1)));
  EXPECT_EQ(view, render_text(with_camera_text(camera_block(*moved.camera))));
}

TEST(ViewCamera, OrbitKeepsTheDistanceAndStopsShortOfTheSky) {
  ViewCamera v;
  v.location = {0, 0, -10};
  const ViewCamera turned = orbit(v, 0.7, 0.3);
  EXPECT_NEAR(glm::length(turned.location - turned.look_at), 10.0, 1e-12);
  const ViewCamera top = orbit(v, 0.0, 10.0);
  EXPECT_LT(glm::dot(glm::normalize(top.location - top.look_at), top.sky), 1.0 - 1e-5);
  EXPECT_NO_THROW(camera_of(top));
  EXPECT_NEAR(glm::length(zoom(v, 0.5).location - v.look_at), 5.0, 1e-12);
}

TEST(ViewCamera, NumbersPrintShortAndExact) {
  EXPECT_EQ(exact_number(0.1), "0.1");
  EXPECT_EQ(exact_number(-3.0), "-3");
  for (double x : {1e-5, 1.0 / 3.0, 12345.678e20, -7e-300}) {
    EXPECT_EQ(std::stod(exact_number(x)), x);
    sdl::ParseOptions p;
    const auto parsed = sdl::parse_string("camera { location <" + exact_number(x) +
                                              ", 0, 0> look_at <0, 0, 1> }",
                                          "n.pov", p);
    EXPECT_EQ(parsed.scene.camera.location.x, x);
  }
}

TEST(ViewEdits, ThePrintedHeaderParsesToTheEditedRadiusAndOffset) {
  ViewSession session(soup_options());
  const auto frame = session.load({});
  ASSERT_EQ(frame->convolutions.size(), 2u);
  const sdl::ConvolutionHeader right = frame->convolutions[1];
  EXPECT_EQ(right.radius, 0.45);
  EXPECT_EQ(header_offset(right), 0.12);
  const sdl::ConvolutionHeader edited = edited_header(edited_header(right, 'R'), 'o');
  EXPECT_EQ(edited.radius, 0.495);
  EXPECT_EQ(*edited.offset, 0.0953);  // 0.12 - 0.05 * 0.495 = 0.09525, to three digits
  auto log = std::make_shared<sdl::ParseLog>();
  sdl::ParseOptions p;
  p.log = log;
  sdl::parse_string(convolution_header_text(edited) + "point { <0, 0, 0> } }", "h.pov", p);
  ASSERT_EQ(log->convolutions.size(), 1u);
  EXPECT_EQ(log->convolutions[0].radius, edited.radius);
  EXPECT_EQ(log->convolutions[0].offset, edited.offset);
}

TEST(ViewEdits, AnEditRendersAsTheSceneWithThePrintedHeader) {
  ViewSession session(soup_options());
  const sdl::ConvolutionHeader right = session.load({})->convolutions[1];
  const sdl::ConvolutionHeader edited = edited_header(edited_header(right, 'r'), 'O');
  ViewOverrides overrides;
  set_edit(overrides.edits, edited);
  const std::vector<float> view = pixels(session.render(*session.load(overrides), 1));
  // The scene as a person would edit it: the second header's lines replaced.
  std::string text = read_text(kSoup);
  const std::string old = "convolution {\n  radius 0.45\n  offset 0.12\n";
  const size_t at = text.find(old);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, old.size(), convolution_header_text(edited));
  EXPECT_EQ(view, render_text(text));
  EXPECT_NE(view, render_text(read_text(kSoup)));
}

TEST(ViewSession, PicksTheConvolutionUnderThePixel) {
  ViewSession session(soup_options());
  const auto frame = session.load({});
  const auto left = convolution_at(*frame, kW, kH, kW / 2 - 16, kH / 2 + 2);
  const auto right = convolution_at(*frame, kW, kH, kW / 2 + 16, kH / 2 + 2);
  ASSERT_TRUE(left && right);
  EXPECT_EQ(left->radius, 0.15);
  EXPECT_EQ(right->radius, 0.45);
  EXPECT_FALSE(convolution_at(*frame, kW, kH, 1, 1));       // the background
  EXPECT_FALSE(convolution_at(*frame, kW, kH, 1, kH - 2));  // the floor
}

// Members of one union (placed by the union's transform too), and a member carved by CSG:
// each pixel picks the convolution whose own surface it shows.
TEST(ViewSession, PicksTheMemberOfAUnionUnderThePixel) {
  const fs::path dir = fs::temp_directory_path() / ("convray-pick-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string text = read_text(kSoup);
  const size_t begin = text.find("object { Soup");
  text = text.substr(0, begin) +
         "union {\n"
         "  object { Soup translate -1.3 * x }\n"
         "  difference {\n"
         "    convolution { radius 0.45 offset 0.12 mesh { \"models/soup.obj\" } }\n"
         "    box { <-2, -2, -2>, <2, 2, -0.5> }\n"
         "    translate 1.3 * x\n"
         "  }\n"
         "  texture { Clay }\n"
         "  translate 0.1 * y\n"
         "}\n";
  write_text((dir / "scene.pov").string(), text);
  ViewOptions o = soup_options();
  o.input = (dir / "scene.pov").string();
  o.library_paths = {kScenes};
  ViewSession session(o);
  const auto frame = session.load({});
  const auto left = convolution_at(*frame, kW, kH, kW / 2 - 16, kH / 2 + 2);
  const auto right = convolution_at(*frame, kW, kH, kW / 2 + 16, kH / 2 + 2);
  ASSERT_TRUE(left && right);
  EXPECT_EQ(left->radius, 0.15);
  EXPECT_EQ(right->radius, 0.45);  // the second member, inside a difference
  EXPECT_FALSE(convolution_at(*frame, kW, kH, 1, 1));
  fs::remove_all(dir);
}

// A mesh is shown as `convray quick` renders it (its radius, framing, light and clay): the
// session's picture in the PNG writer's 8-bit levels against quick's file, read back by
// libpng (reference/png_pixels.hpp).
TEST(ViewSession, AMeshLooksAsQuickRendersIt) {
  const std::string mesh = kScenes + "/models/soup.obj";
  const fs::path png = fs::temp_directory_path() / ("convray-quick-" + std::to_string(::getpid()) + ".png");
  const std::string command = std::string(CONVRAY_BINARY) + " quick " + mesh + " --size " +
                              std::to_string(kW) + "x" + std::to_string(kH) + " -o " +
                              png.string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const reference::PngPixels read = reference::read_png_rgb8(png.string());
  ASSERT_EQ(read.width, kW) << read.error;
  ASSERT_EQ(read.height, kH);
  const std::vector<uint8_t>& quick = read.rgb;
  fs::remove(png);

  ViewOptions o = soup_options();
  o.input = mesh;
  ViewSession session(o);
  const std::vector<float> film = pixels(session.render(*session.load({}), 1));
  ASSERT_EQ(film.size(), quick.size());
  size_t off_by_more_than_one = 0;
  for (size_t k = 0; k < film.size(); ++k) {
    const int level = quantize_8bit(encode_srgb(film[k]));
    off_by_more_than_one += std::abs(level - int(quick[k])) > 1;
  }
  EXPECT_EQ(off_by_more_than_one, 0u);
}

TEST(ViewSession, WatchesTheSceneItsIncludesAndMeshes) {
  const fs::path dir = fs::temp_directory_path() / ("convray-view-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_text((dir / "lights.inc").string(), "light_source { <-6, 9, -7> color rgb 1 }\n");
  std::string text = read_text(kSoup);
  text.replace(text.find("light_source"), 0, "#include \"lights.inc\"\n");
  write_text((dir / "scene.pov").string(), text);
  ViewOptions o = soup_options();
  o.input = (dir / "scene.pov").string();
  o.library_paths = {kScenes};
  ViewSession session(o);
  session.load({});
  const std::vector<std::string> files = session.watched_files();
  auto has = [&](const std::string& end) {
    return std::any_of(files.begin(), files.end(), [&](const std::string& f) {
      return f.size() >= end.size() && f.compare(f.size() - end.size(), end.size(), end) == 0;
    });
  };
  EXPECT_TRUE(has("scene.pov"));
  EXPECT_TRUE(has("lights.inc"));
  EXPECT_TRUE(has("models/soup.obj"));
  FileWatch watch;
  watch.watch(files);
  EXPECT_FALSE(watch.changed());
  write_text((dir / "lights.inc").string(), "light_source { <-6, 9, -7> color rgb 0.5 }\n");
  EXPECT_TRUE(watch.changed());
  EXPECT_FALSE(watch.changed());
  fs::remove_all(dir);
}

TEST(ViewSession, AMissingIncludeIsWatchedWhereItWasLookedFor) {
  const fs::path dir = fs::temp_directory_path() / ("convray-view-m" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_text((dir / "scene.pov").string(), "#include \"later.inc\"\nsphere { 0, 1 }\n");
  ViewOptions o = soup_options();
  o.input = (dir / "scene.pov").string();
  ViewSession session(o);
  EXPECT_THROW(session.load({}), InputError);
  FileWatch watch;
  watch.watch(session.watched_files());
  write_text((dir / "later.inc").string(), "light_source { <0, 5, -5> color rgb 1 }\n");
  EXPECT_TRUE(watch.changed());
  EXPECT_NO_THROW(session.load({}));
  fs::remove_all(dir);
}

TEST(FileWatch, AFileWatchedBeforeKeepsItsReferenceWhenTheListChanges) {
  const fs::path dir = fs::temp_directory_path() / ("convray-view-w" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string scene = (dir / "scene.pov").string(), mesh = (dir / "mesh.obj").string();
  write_text(scene, "");  // an editor's save caught between truncation and write
  write_text(mesh, "v 0 0 0\n");
  FileWatch watch;
  watch.watch({scene, mesh});
  write_text(scene, "sphere { 0, 1 }\n");  // the write lands before the list is renewed
  watch.watch({scene});                     // the empty scene's parse read no mesh
  EXPECT_TRUE(watch.changed());
  fs::remove_all(dir);
}

// Waits (up to a minute) until the worker has answered request `number` with `stage`.
ViewWorker::State wait_for(const ViewWorker& worker, uint64_t number, ViewWorker::Stage stage) {
  for (int i = 0; i < 6000; ++i) {
    const ViewWorker::State s = worker.state();
    if (s.request == number && s.stage == stage) return s;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ADD_FAILURE() << "no answer";
  return worker.state();
}

TEST(ViewWorker, AParseErrorKeepsTheLastGoodPictureAndSaysWhere) {
  const fs::path dir = fs::temp_directory_path() / ("convray-view-e" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string scene = (dir / "scene.pov").string();
  write_text(scene, with_camera_text("camera { location <0, 2, -6> look_at <0, 0, 0> }\n"));
  ViewOptions o = soup_options();
  o.input = scene;
  o.library_paths = {kScenes};
  ViewSession session(o);
  display::PreviewImage image({0, 0, kW, kH}, {kW, kH});
  ViewWorker worker(session, image);
  const ViewWorker::State good =
      wait_for(worker, worker.request({}, true), ViewWorker::Stage::done);
  std::vector<uint8_t> before, after;
  image.take_if_changed(before);
  // The file render's bytes are what the window shows.
  const std::vector<float> file = render_text(read_text(scene));
  EXPECT_EQ(*good.picture, file);

  write_text(scene, "sphere { <0, 0, 0>, 1\n  pigment { colour rgb 1 }\n  oops\n}\n");
  const ViewWorker::State bad =
      wait_for(worker, worker.request({}, true), ViewWorker::Stage::failed);
  ASSERT_TRUE(bad.error);
  EXPECT_EQ(bad.error->rfind(scene + ":3:3: ", 0), 0u) << *bad.error;
  EXPECT_EQ(bad.frame, good.frame);  // the last good scene stays
  image.mark_changed();
  image.take_if_changed(after);
  EXPECT_EQ(after, before);
  fs::remove_all(dir);
}

TEST(ViewSession, TheClockIsTheScenesClock) {
  const fs::path dir = fs::temp_directory_path() / ("convray-view-c" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string scene = (dir / "clock.pov").string();
  const std::string text =
      "camera { location <0, 0, -4> look_at 0 }\nlight_source { <2, 4, -3> color rgb 1 }\n"
      "sphere { <2 * clock - 1, 0, 0>, 0.5 pigment { rgb <1, clock, 0> } }\n";
  write_text(scene, text);
  ViewOptions o = soup_options();
  o.input = scene;
  ViewSession session(o);
  ViewOverrides at;
  at.clock = 0.75;
  const std::vector<float> view = pixels(session.render(*session.load(at), 1));
  // The plain parser and renderer, told clock = 0.75 as an animation frame is.
  sdl::ParseOptions p;
  p.image_width = kW;
  p.image_height = kH;
  p.clock = 0.75;
  const sdl::ParseResult parsed = sdl::parse_string(text, scene, p);
  render::RenderSettings s;
  s.width = kW;
  s.height = kH;
  const render::RenderResult plain =
      render::render_scene(parsed.scene, geometry::World(parsed.scene), s);
  EXPECT_EQ(view, pixels(plain));
  EXPECT_NE(view, pixels(session.render(*session.load({}), 1)));
  fs::remove_all(dir);
}

TEST(ViewSession, AMeshBecomesQuicksScene) {
  ViewOptions o = soup_options();
  o.input = kScenes + "/models/soup.obj";
  ViewSession session(o);
  const auto frame = session.load({});
  ASSERT_EQ(frame->convolutions.size(), 1u);
  const std::vector<std::string> files = session.watched_files();
  EXPECT_EQ(files.front(), o.input);
  const render::RenderResult r = session.render(*frame, kCoarseBlock);
  EXPECT_GT(r.stats.hits, 0u);
}

}  // namespace
}  // namespace convray::app
