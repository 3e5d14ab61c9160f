// `convray quick`: a picture only when everything is right, never a partial file, and a clear
// message (exit code 2) otherwise. The renders need the real ConvolutionSurface.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "app/cli.hpp"

namespace convray {
namespace {

const std::string kSoup = "'" + std::string(CONVRAY_SOURCE_DIR) + "/scenes/models/soup.obj'";

class QuickCommand : public testing::CliTest {
 protected:
  // Nothing but the files the test made itself: no image, no `.partial` left over.
  size_t files_in_folder() const {
    size_t n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
      n += entry.path().filename().string()[0] != '.' ||
           entry.path().filename().string().find(".partial") != std::string::npos;
    }
    return n;
  }
  testing::CliRun quick(const std::string& arguments) const {
    return run_convray("quick " + arguments);
  }
};

// A binary PPM (P6, maxval 255) as written by OpenImageIO: read here without it.
struct Ppm {
  int width = -1, height = -1;
  std::string pixels;  // 3 bytes per pixel
};

Ppm read_ppm(const std::string& bytes) {
  Ppm ppm;
  int maxval = 0, consumed = 0;
  if (std::sscanf(bytes.c_str(), "P6 %d %d %d%n", &ppm.width, &ppm.height, &maxval, &consumed) !=
          3 ||
      maxval != 255) {
    return {};
  }
  ppm.pixels = bytes.substr(size_t(consumed) + 1);  // one whitespace byte ends the header
  if (ppm.pixels.size() != size_t(ppm.width) * ppm.height * 3) return {};
  return ppm;
}

TEST_F(QuickCommand, HelpSaysWhatItDoesEveryOptionAndAnExample) {
  const testing::CliRun run = quick("--help");
  EXPECT_EQ(run.exit_code, 0);
  for (const std::string text : {"convolution surface",
                                 "MESH",
                                 "--radius",
                                 "--offset",
                                 "--threshold",
                                 "--size",
                                 "--fit-box",
                                 "--camera",
                                 "--look-at",
                                 "--angle",
                                 "--light",
                                 "--reference",
                                 "--stats",
                                 "--output",
                                 "Example: convray quick",
                                 "default 800x600",
                                 "default 40",
                                 "default R/2",
                                 "default quick.png",
                                 "degrees",
                                 "model units"}) {
    EXPECT_NE(run.out.find(text), std::string::npos) << text;
  }
}

TEST_F(QuickCommand, RendersThePictureAndSaysWhatItDid) {
  const testing::CliRun run = quick(kSoup + " --size 48x36 -o '" + file("q.ppm") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("319 triangles"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("wrote"), std::string::npos) << run.out;
  EXPECT_EQ(run.err, "");  // no progress bar into a file
  const Ppm ppm = read_ppm(testing::read_file(file("q.ppm")));
  ASSERT_EQ(ppm.width, 48);
  ASSERT_EQ(ppm.height, 36);
  // Framed automatically: the surface is in the middle, the corners show the background.
  const auto pixel = [&](int i, int j) { return ppm.pixels.substr(3 * (size_t(j) * 48 + i), 3); };
  EXPECT_EQ(pixel(0, 0), pixel(47, 35));
  EXPECT_NE(pixel(24, 18), pixel(0, 0));
  EXPECT_EQ(files_in_folder(), 1u);
}

TEST_F(QuickCommand, StatsListEveryCounterAndPhaseOnItsOwnLine) {
  const testing::CliRun run = quick(kSoup + " --size 32x24 --stats -o '" + file("q.png") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  for (const std::string item :
       {"image: 32x24", "rays: ", "primitives per ray: ", "field evaluations: ", "roots: ",
        "fits: ", "subdivisions: ", "fallbacks: ", "shadow rays settled inside: ",
        "surface memory: ", "time load: ",
        "time build: ", "time render: ", "time write: "}) {
    EXPECT_NE(run.out.find("\n" + item), std::string::npos) << item;
  }
  EXPECT_NE(run.out.find("(camera 768, shadow "), std::string::npos) << run.out;
}

// The bar for the fast path: at most 0.05% of pixels may disagree with the exact
// reference tracer; at 64x48 that is one pixel. Shading may differ in the last 8-bit level.
TEST_F(QuickCommand, FastAndReferenceTracersDrawTheSamePicture) {
  const std::string common = kSoup + " --size 64x48 ";
  ASSERT_EQ(quick(common + "-o '" + file("fast.ppm") + "'").exit_code, 0);
  const testing::CliRun run =
      quick(common + "--reference --stats -o '" + file("reference.ppm") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("tracer: reference"), std::string::npos);
  const Ppm fast = read_ppm(testing::read_file(file("fast.ppm")));
  const Ppm reference = read_ppm(testing::read_file(file("reference.ppm")));
  ASSERT_EQ(fast.pixels.size(), reference.pixels.size());
  ASSERT_FALSE(fast.pixels.empty());
  int differing = 0;
  for (size_t p = 0; p < fast.pixels.size(); p += 3) {
    bool differs = false;
    for (size_t c = 0; c < 3; ++c) {
      differs |= std::abs(int((unsigned char)fast.pixels[p + c]) -
                          int((unsigned char)reference.pixels[p + c])) > 1;
    }
    differing += differs;
  }
  EXPECT_LE(differing, 1);
}

TEST_F(QuickCommand, FitBoxScalesTheModelAndTheAdvisedRadius) {
  // soup.obj's largest extent is 2.25424 and its mean edge 0.29888: `info` advises a tenth of
  // the extent, 0.225424; in the 400 box that is 40.
  testing::CliRun run = quick(kSoup + " --size 16x12 -o '" + file("a.png") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("R = 0.225424,"), std::string::npos) << run.out;
  run = quick(kSoup + " --size 16x12 --fit-box 400 -o '" + file("b.png") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("R = 40,"), std::string::npos) << run.out;
  // The offset default, R/2, gives T = (pi/3) (R^2 - R^2/4)^3 / R^4 = (pi/3) (27/64) R^2.
  EXPECT_NE(run.out.find("T = 706.858"), std::string::npos) << run.out;
}

TEST_F(QuickCommand, ExplicitCameraLightAndThreshold) {
  const testing::CliRun run = quick(kSoup +
                                    " --size 24x16 --camera 0.5,1,-6 --look-at 0,0,0 --angle 30 "
                                    "--light -3,4,-5 --radius 0.3 --threshold 0.02 -o '" +
                                    file("c.tif") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("T = 0.02)"), std::string::npos) << run.out;
  EXPECT_TRUE(std::filesystem::exists(file("c.tif")));
}

TEST_F(QuickCommand, BadInputFailsWithExitCode2AndNoImage) {
  const std::string out = " -o '" + file("q.png") + "'";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"'" + file("missing.obj") + "'", "missing.obj: cannot open the file"},
      {kSoup + " --radius abc", "--radius: expected a number, got 'abc'"},
      {kSoup + " --radius 0", "--radius: must be > 0"},
      {kSoup + " --radius inf", "--radius: must be finite"},
      {kSoup + " --size 64by48", "expected WIDTHxHEIGHT"},
      {kSoup + " --size 0x48", "expected WIDTHxHEIGHT"},
      {kSoup + " --offset 0.1 --threshold 0.2", "--offset excludes --threshold"},
      {kSoup + " --radius 0.3 --offset 0.3", "--offset must satisfy 0 <= offset < radius"},
      {kSoup + " --radius 0.3 --offset -0.1", "--offset must satisfy 0 <= offset < radius"},
      {kSoup + " --offset 5",
       "--offset must satisfy 0 <= offset < radius"},  // against the advised R
      {kSoup + " --threshold -1", "--threshold: must be > 0"},
      {kSoup + " --fit-box 0", "--fit-box: must be > 0"},
      {kSoup + " --camera 0,0,-5", "--camera requires --look-at"},
      {kSoup + " --look-at 0,0,0", "--look-at requires --camera"},
      {kSoup + " --camera 0,0 --look-at 0,0,0", "--camera: expected X,Y,Z"},
      {kSoup + " --camera 0,0,-5,1 --look-at 0,0,0", "--camera: expected X,Y,Z"},
      {kSoup + " --camera 0,0,x --look-at 0,0,0", "--camera: expected X,Y,Z"},
      {kSoup + " --camera '0, 0, -5' --look-at 0,0,0", "--camera: expected X,Y,Z"},
      {kSoup + " --camera 0,0,-5 --look-at 0,nan,0", "--look-at: expected X,Y,Z"},
      {kSoup + " --light 1e999,0,0", "--light: expected X,Y,Z"},
      {kSoup + " --camera 1,2,3 --look-at 1,2,3",
       "--camera/--look-at: the camera location and look_at must be distinct"},
      {kSoup + " --camera 0,5,0 --look-at 0,0,0", "must not be vertical"},
      {kSoup + " --angle 0", "--angle: expected degrees with 0 < angle < 180"},
      {kSoup + " --angle 180", "--angle: expected degrees with 0 < angle < 180"},
      {kSoup + " --frobnicate", "--frobnicate"},
  };
  for (const auto& [arguments, message] : cases) {
    const testing::CliRun run = quick(arguments + out);
    EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.all();
    EXPECT_NE(run.err.find(message), std::string::npos) << arguments << "\n" << run.err;
    EXPECT_EQ(files_in_folder(), 0u) << arguments;
  }
}

TEST_F(QuickCommand, UnwritableOutputFailsBeforeRendering) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {file("q.notanimage"), "cannot write images of type '.notanimage'"},
      {file("q"), "needs an extension"},
      {file("no/such/folder/q.png"), "folder '" + file("no/such/folder") + "' does not exist"},
  };
  for (const auto& [output, message] : cases) {
    const testing::CliRun run =
        quick(kSoup + " --reference -o '" + output + "'");  // would take long
    EXPECT_EQ(run.exit_code, 2) << output << "\n" << run.all();
    EXPECT_NE(run.err.find(output + ": "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
    EXPECT_EQ(files_in_folder(), 0u) << output;
  }
}

}  // namespace
}  // namespace convray
