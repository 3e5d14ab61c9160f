// Partial renders (+SC/+EC/+SR/+ER, Start_Column/End_Column/Start_Row/End_Row): which pixels
// the bounds select, as POV-Ray 3.7.0.10 selects them (measured: docs in partial_image.hpp),
// what is written (the whole picture, black elsewhere, as POV-Ray writes it), and that the
// selected pixels are exactly those of one render of the whole picture, anti-aliasing and
// jitter included, so that parts rendered apart stitch into that picture.
#include "app/partial_image.hpp"

#include <gtest/gtest.h>

#include "app/render_options.hpp"
#include "povray_pictures.hpp"

namespace convray::app {
namespace {

render::PixelWindow window_of(std::vector<std::string> args) {
  args.insert(args.begin(), {"scene.pov", "+W64", "+H48"});
  const RenderOptions o = parse_render_arguments(args);
  EXPECT_TRUE(o.window.has_value());
  return o.window.value_or(render::PixelWindow{});
}

std::string error_of(std::vector<std::string> args) {
  args.insert(args.begin(), {"scene.pov", "+W64", "+H48"});
  try {
    parse_render_arguments(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

// Rows [y0, y1) and columns [x0, x1), counted from 0.
void expect_window(const render::PixelWindow& w, int x0, int x1, int y0, int y1) {
  EXPECT_EQ(w.x0, x0);
  EXPECT_EQ(w.x1, x1);
  EXPECT_EQ(w.y0, y0);
  EXPECT_EQ(w.y1, y1);
}

TEST(PartialImage, NoBoundsIsTheWholePicture) {
  EXPECT_FALSE(parse_render_arguments({"scene.pov"}).window.has_value());
}

// Each line: what POV-Ray 3.7.0.10 rendered at +W64 +H48 (the rows and columns it reported,
// and the non-black box of its picture), from 1; here from 0, end excluded.
TEST(PartialImage, PixelNumbersAndFractionsAsPovRayReadsThem) {
  expect_window(window_of({"+SR10", "+ER20"}), 0, 64, 9, 20);
  expect_window(window_of({"+SR0.25", "+ER0.5"}), 0, 64, 12, 24);
  expect_window(window_of({"+SR0.5", "+ER1.0"}), 0, 64, 24, 48);
  expect_window(window_of({"+SR1", "+ER1"}), 0, 64, 0, 48);  // start 1: row 1; end 1: all
  expect_window(window_of({"+SR0", "+ER0.5"}), 0, 64, 0, 24);
  expect_window(window_of({"+SC0.5", "+EC0.75"}), 32, 48, 0, 48);
  expect_window(window_of({"+SR10.7", "+ER20.7"}), 0, 64, 9, 20);  // fractions dropped
  expect_window(window_of({"+SR48", "+ER48"}), 0, 64, 47, 48);
  expect_window(window_of({"+SR1", "+ER1.5"}), 0, 64, 0, 1);
  expect_window(window_of({"+SR0.02", "+ER2"}), 0, 64, 0, 2);
  expect_window(window_of({"+SC1.9", "+EC2.9", "+SR5", "+ER5"}), 0, 2, 4, 5);
  expect_window(window_of({"+SR10", "+ER20", "+SC5", "+EC30"}), 4, 30, 9, 20);
}

TEST(PartialImage, AStartAfterTheEndRendersNothingWithoutAnError) {
  EXPECT_TRUE(window_of({"+SR20", "+ER10"}).empty());
  EXPECT_TRUE(window_of({"+SR0.999", "+ER0.999"}).empty());  // POV-Ray: rows 48 to 47
}

TEST(PartialImage, BoundsOutsideThePictureAreErrorsAsInPovRay) {
  // POV-Ray: "Invalid start column or row" / "Invalid end column or row".
  EXPECT_NE(error_of({"+SR100"}).find("+SR100: the start row 100 is outside the picture"),
            std::string::npos)
      << error_of({"+SR100"});
  EXPECT_NE(error_of({"+ER100"}).find("the end row 100 is outside"), std::string::npos);
  EXPECT_NE(error_of({"+SR-5"}).find("the start row -5 is outside"), std::string::npos);
  EXPECT_NE(error_of({"+ER0"}).find("the end row 0 is outside"), std::string::npos);
  EXPECT_NE(error_of({"+ER0.01"}).find("end row"), std::string::npos);  // int(0.48) - 1 < 0
  EXPECT_NE(error_of({"+SC65"}).find("give a column number from 1 to 64, or a fraction"),
            std::string::npos)
      << error_of({"+SC65"});
  EXPECT_NE(error_of({"+SRx"}).find("+SRx: expected a number"), std::string::npos);
  EXPECT_NE(error_of({"Start_Row=200"}).find("Start_Row: the start row 200"), std::string::npos);
}

TEST(PartialImage, IniKeysLongOptionsAndSwitchesAgree) {
  const render::PixelWindow by_switch = window_of({"+SC3", "+EC40", "+SR0.25", "+ER30"});
  expect_window(window_of({"Start_Column=3", "End_Column=40", "start_row=0.25", "END_ROW=30"}),
                by_switch.x0, by_switch.x1, by_switch.y0, by_switch.y1);
  expect_window(window_of({"--start-column", "3", "--end-column=40", "--start-row", "0.25",
                           "--end-row", "30"}),
                by_switch.x0, by_switch.x1, by_switch.y0, by_switch.y1);
  expect_window(window_of({"-sc3", "-EC40", "+sr0.25", "+er30"}), by_switch.x0, by_switch.x1,
                by_switch.y0, by_switch.y1);
}

TEST(PartialImage, FractionsApplyToTheFinalSizeWhereverItIsGiven) {
  // +SR0.5 before +H100: half of 100 rows, as POV-Ray reads every option before rendering.
  const RenderOptions o = parse_render_arguments({"scene.pov", "+SR0.5", "+H100", "+W10"});
  ASSERT_TRUE(o.window);
  expect_window(*o.window, 0, 10, 50, 100);
}

}  // namespace
}  // namespace convray::app

namespace convray::testing {
namespace {

// Nothing in it is black, so a black pixel of a partial render was not rendered.
constexpr const char* kScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at 0 }
light_source { <3, 5, -5> color rgb 1 }
background { color rgb <0.2, 0.3, 0.8> }
sphere { 0, 1 pigment { checker color rgb <1, 0.5, 0.2> color rgb <0.2, 0.9, 0.3> scale 0.3 }
         finish { ambient 0.2 } }
plane { y, -1 pigment { checker color rgb 1 color rgb 0.4 } finish { ambient 0.2 } }
)";

class PartialRender : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    std::ofstream(file("scene.pov")) << kScene;
  }

  // Renders scene.pov into NAME.png with `switches` and returns its 8-bit pixels.
  std::vector<unsigned char> render(const std::string& name, const std::string& switches) {
    const CliRun run = run_convray("'" + file("scene.pov") + "' -o '" + file(name + ".png") +
                                   "' --quiet " + switches);
    EXPECT_EQ(run.exit_code, 0) << run.all();
    return read_rgb8(file(name + ".png"));
  }

  static constexpr int kWidth = 64, kHeight = 48;
};

// Pixels of `part` inside columns [x0, x1) and rows [y0, y1) equal `full`'s; all others black.
void expect_part_of(const std::vector<unsigned char>& part, const std::vector<unsigned char>& full,
                    int width, int x0, int x1, int y0, int y1) {
  ASSERT_EQ(part.size(), full.size());
  int differing = 0, lit_outside = 0;
  for (size_t k = 0; k < full.size(); ++k) {
    const int i = int(k / 3) % width, j = int(k / 3) / width;
    if (i >= x0 && i < x1 && j >= y0 && j < y1) {
      differing += part[k] != full[k];
    } else {
      lit_outside += part[k] != 0;
    }
  }
  EXPECT_EQ(differing, 0);
  EXPECT_EQ(lit_outside, 0);
}

TEST_F(PartialRender, AntialiasedAndJitteredPixelsAreTheWholeRendersPixels) {
  const std::string aa = " +W64 +H48 +A0.05 +R3 +J +WT2";
  const std::vector<unsigned char> full = render("full", aa);
  // Rows 10-20 and columns 5-30: the neighbours that decide anti-aliasing lie outside.
  expect_part_of(render("part", aa + " +SR10 +ER20 +SC5 +EC30"), full, kWidth, 4, 30, 9, 20);
  expect_part_of(render("edge", aa + " +SR48 +ER48"), full, kWidth, 0, 64, 47, 48);
  expect_part_of(render("one", aa + " +SR7 +ER7 +SC9 +EC9"), full, kWidth, 8, 9, 6, 7);
}

TEST_F(PartialRender, BandsOfRowsAddUpToTheWholePicture) {
  const std::string aa = " +W64 +H48 +A0.05 +WT1";
  const std::vector<unsigned char> full = render("full", aa);
  const std::vector<unsigned char> a = render("a", aa + " +SR0 +ER0.333333333");
  const std::vector<unsigned char> b = render("b", aa + " +SR0.333333333 +ER0.666666667");
  const std::vector<unsigned char> c = render("c", aa + " +SR0.666666667 +ER1");
  ASSERT_EQ(a.size(), full.size());
  ASSERT_EQ(b.size(), full.size());
  ASSERT_EQ(c.size(), full.size());
  std::vector<unsigned char> stitched(full.size());
  for (size_t k = 0; k < full.size(); ++k) stitched[k] = std::max({a[k], b[k], c[k]});
  EXPECT_EQ(stitched, full);
}

TEST_F(PartialRender, FractionAndPixelFormsWriteTheSameFile) {
  render("fraction", "+W64 +H48 +SR0.25 +ER0.5 +SC0.5 +EC1");
  render("pixels", "+W64 +H48 +SR13 +ER24 +SC33 +EC64");
  EXPECT_EQ(read_file(file("fraction.png")), read_file(file("pixels.png")));
  std::ofstream(file("part.ini")) << "Width=64\nHeight=48\nStart_Row=13\nEnd_Row=24\n"
                                     "Start_Column=0.5\nEnd_Column=64\n";
  render("ini", "'" + file("part.ini") + "'");
  EXPECT_EQ(read_file(file("ini.png")), read_file(file("pixels.png")));
}

TEST_F(PartialRender, AnEmptyPartWritesABlackPictureAndSaysSo) {
  const CliRun run = run_convray("'" + file("scene.pov") + "' -o '" + file("empty.png") +
                                 "' +W64 +H48 +SR20 +ER10");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.err.find("start is after its end"), std::string::npos) << run.err;
  const std::vector<unsigned char> empty = read_rgb8(file("empty.png"));
  ASSERT_EQ(empty.size(), size_t(kWidth) * kHeight * 3);
  EXPECT_EQ(std::count(empty.begin(), empty.end(), 0), ptrdiff_t(empty.size()));
}

TEST_F(PartialRender, BoundsOutsideThePictureFailBeforeAnyWork) {
  const CliRun run = run_convray("'" + file("scene.pov") + "' -o '" + file("bad.png") +
                                 "' +W64 +H48 +SR10 +ER49");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("+ER49: the end row 49 is outside the picture"), std::string::npos)
      << run.err;
  EXPECT_FALSE(std::filesystem::exists(file("bad.png")));
}

// scripts/stitch-parts.sh, as docs/render-farm.md tells users to run it: rows and columns mixed.
TEST_F(PartialRender, StitchPartsScriptGivesTheWholePicture) {
  if (std::system("command -v oiiotool > /dev/null") != 0) {
    GTEST_SKIP() << "oiiotool is not installed (Debian package openimageio-tools)";
  }
  const std::string aa = " +W64 +H48 +A0.05 +J";
  const std::vector<unsigned char> full = render("full", aa);
  render("top", aa + " +SR1 +ER20");
  render("left", aa + " +SR21 +ER48 +SC1 +EC30");
  render("right", aa + " +SR21 +ER48 +SC0.453125 +EC1");  // from column 30: one overlaps
  const std::string stitch = "bash '" + std::string(CONVRAY_SOURCE_DIR) +
                             "/scripts/stitch-parts.sh' ";
  const std::string in_dir = "cd '" + dir_.string() + "' && ";
  ASSERT_EQ(std::system((in_dir + stitch + "whole.png top.png left.png right.png > log 2>&1")
                            .c_str()),
            0)
      << read_file(file("log"));
  EXPECT_EQ(read_rgb8(file("whole.png")), full);
  // Parts of different sizes are refused, and nothing is written.
  render("small", " +W32 +H48 +SR1 +ER10");
  EXPECT_NE(std::system((in_dir + stitch + "bad.png top.png small.png > log 2>&1").c_str()), 0);
  EXPECT_NE(read_file(file("log")).find("parts of one picture must agree"), std::string::npos)
      << read_file(file("log"));
  EXPECT_FALSE(std::filesystem::exists(file("bad.png")));
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename().string().find(".stitch"), std::string::npos);
  }
}

TEST_F(PartialRender, HelpNamesTheOptions) {
  const CliRun run = run_convray("render --help");
  EXPECT_EQ(run.exit_code, 0);
  for (const char* name : {"--start-row N, --end-row M", "+SRN +ERM", "Start_Column=",
                           "scripts/stitch-parts.sh"}) {
    EXPECT_NE(run.out.find(name), std::string::npos) << name << "\n" << run.out;
  }
}

// POV-Ray renders the same rectangle: its picture's non-black pixels are where ours are.
TEST_F(PartialRender, PovRayRendersTheSameRectangle) {
  SKIP_WITHOUT_POVRAY();
  for (const std::string bounds : {"+SR10 +ER20 +SC5 +EC30", "+SR0.25 +ER0.5", "+SC0.5 +EC0.75",
                                   "+SR10.7 +ER20.7 +SC1.9 +EC2.9", "+SR48 +ER48 +SC0 +EC1"}) {
    const std::string switches = " +W64 +H48 -A " + bounds;
    const std::vector<unsigned char> ours = render("ours", switches);
    const std::string pov = "cd '" + dir_.string() + "' && povray +Iscene.pov +Opov.png -D -GA" +
                            switches + " > /dev/null 2>&1";
    ASSERT_EQ(std::system(pov.c_str()), 0) << pov;
    const std::vector<unsigned char> theirs = read_rgb8(file("pov.png"));
    ASSERT_EQ(theirs.size(), ours.size()) << bounds;
    int different = 0;
    for (size_t p = 0; p < ours.size(); p += 3) {
      const bool ours_lit = ours[p] || ours[p + 1] || ours[p + 2];
      const bool theirs_lit = theirs[p] || theirs[p + 1] || theirs[p + 2];
      different += ours_lit != theirs_lit;
    }
    EXPECT_EQ(different, 0) << bounds;
  }
}

}  // namespace
}  // namespace convray::testing
