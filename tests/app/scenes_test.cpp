// Every scene in scenes/ renders: parsed, built and traced at a small size, exit code 0, a PNG
// written. (The pictures in docs/ come from the same files at full size:
// scripts/make-docs-images.sh.) Also the render command's errors, end to end.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli.hpp"

namespace convray {
namespace {

class Scenes : public testing::CliTest {};

std::vector<std::filesystem::path> scene_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(CONVRAY_SOURCE_DIR "/scenes")) {
    if (entry.path().extension() == ".pov") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST_F(Scenes, ThereAreAtLeastEight) { EXPECT_GE(scene_files().size(), 8u); }

TEST_F(Scenes, EachRendersAtSmallSize) {
  for (const std::filesystem::path& scene : scene_files()) {
    const std::string png = file(scene.stem().string() + ".png");
    const testing::CliRun run =
        run_convray("'" + scene.string() + "' +W64 +H48 --quiet -o '" + png + "'");
    EXPECT_EQ(run.exit_code, 0) << scene << "\n" << run.all();
    EXPECT_TRUE(std::filesystem::exists(png)) << scene;
    EXPECT_GT(std::filesystem::file_size(png), 100u) << scene;
  }
}

TEST_F(Scenes, PovRayStyleCommandLineWorks) {
  std::ofstream(file("ball.pov")) << "camera { location <0, 0, -5> look_at 0 }\n"
                                     "light_source { <5, 5, -5> color rgb 1 }\n"
                                     "sphere { 0, 1 pigment { color rgb <1, 0, 0> } }\n";
  const testing::CliRun run = run_convray("+I'" + file("ball.pov") + "' +O'" + file("ball.png") +
                                          "' +W40 +H30 +A0.3 -D +WT2");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_TRUE(std::filesystem::exists(file("ball.png")));
}

TEST_F(Scenes, SceneErrorsPointAtTheSourceAndWriteNoImage) {
  std::ofstream(file("bad.pov")) << "camera { location <0, 0, -5> look_at 0 }\n"
                                    "sphere { 0, 1 texure { } }\n";
  const testing::CliRun run =
      run_convray("'" + file("bad.pov") + "' +W40 +H30 -o '" + file("bad.png") + "'");
  EXPECT_EQ(run.exit_code, 2) << run.all();
  EXPECT_NE(run.err.find("bad.pov:2:15:"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(file("bad.png")));
}

TEST_F(Scenes, MissingSceneIsNamed) {
  const testing::CliRun run = run_convray("'" + file("nowhere.pov") + "' -o '" + file("x.png") + "'");
  EXPECT_EQ(run.exit_code, 2) << run.all();
  EXPECT_NE(run.err.find("nowhere.pov"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace convray
