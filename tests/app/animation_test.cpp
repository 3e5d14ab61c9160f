// The animation's frames and clock identifiers, frame file names, and INI files.
//
// Expected values are POV-Ray 3.7.0's, as `povray` printed them for a scene that #debugs every
// identifier (the option sets below, rendered with Debian's povray 3.7.0.10), and as its
// documentation defines them: clock = initial_clock + (final_clock - initial_clock) *
// (frame - initial_frame) / (final_frame - initial_frame), the divisor one larger with +KC.
// animation_cli_test.cpp runs the same comparison live against the povray binary.
#include "app/animation.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "reference/test_folder.hpp"
#include "app/frame_names.hpp"
#include "app/ini_file.hpp"
#include "app/render_options.hpp"

namespace convray::app {
namespace {

FramePlan plan(std::vector<std::string> switches) {
  switches.insert(switches.begin(), "scene.pov");
  return plan_frames(parse_render_arguments(switches).animation);
}

std::vector<long long> frame_numbers(const FramePlan& p) {
  std::vector<long long> numbers;
  for (const FrameClock& f : p.frames) numbers.push_back(f.frame_number);
  return numbers;
}

using Frames = std::vector<long long>;

TEST(AnimationPlan, AStillHasPovRaysIdentifiers) {
  FramePlan p = plan({});
  ASSERT_EQ(p.frames.size(), 1u);
  EXPECT_FALSE(p.animated);
  EXPECT_EQ(p.frames[0].clock, 0.0);
  EXPECT_FALSE(p.frames[0].clock_on);
  EXPECT_EQ(p.frames[0].frame_number, 0);
  EXPECT_EQ(p.frames[0].final_frame, 0);
  // +K sets clock_on for a still; +KI/+KF/+KC alone do not make an animation.
  p = plan({"+K0.7"});
  EXPECT_FALSE(p.animated);
  EXPECT_DOUBLE_EQ(p.frames[0].clock, 0.7);
  EXPECT_TRUE(p.frames[0].clock_on);
  p = plan({"+KI0.5", "+KF2", "+KC"});
  EXPECT_FALSE(p.animated);
  EXPECT_EQ(p.frames[0].clock, 0.0);
  EXPECT_EQ(p.frames[0].initial_clock, 0.0);  // POV-Ray reports 0 for a still
}

TEST(AnimationPlan, FinalFrameAloneRunsTheClockFromZeroToOne) {
  const FramePlan p = plan({"+KFF5"});
  EXPECT_TRUE(p.animated);
  EXPECT_EQ(frame_numbers(p), (Frames{1, 2, 3, 4, 5}));
  const double clocks[] = {0.0, 0.25, 0.5, 0.75, 1.0};
  for (size_t i = 0; i < 5; ++i) {
    EXPECT_DOUBLE_EQ(p.frames[i].clock, clocks[i]);
    EXPECT_DOUBLE_EQ(p.frames[i].clock_delta, 0.25);
    EXPECT_TRUE(p.frames[i].clock_on);
    EXPECT_EQ(p.frames[i].initial_frame, 1);
    EXPECT_EQ(p.frames[i].final_frame, 5);
    EXPECT_EQ(p.frames[i].initial_clock, 0.0);
    EXPECT_EQ(p.frames[i].final_clock, 1.0);
  }
  EXPECT_EQ(p.name_digits, 1);
}

TEST(AnimationPlan, CyclicStopsOneStepShortAndReportsTheExtraFrame) {
  const FramePlan p = plan({"+KFF5", "+KC"});
  EXPECT_EQ(frame_numbers(p), (Frames{1, 2, 3, 4, 5}));
  EXPECT_DOUBLE_EQ(p.frames[4].clock, 0.8);
  EXPECT_DOUBLE_EQ(p.frames[0].clock_delta, 0.2);
  EXPECT_EQ(p.frames[0].final_frame, 6);  // POV-Ray's final_frame reads 6
  // +KFF9 +KC: final_frame reads 10, so names get two digits (c01.png ... c09.png).
  EXPECT_EQ(plan({"+KFF9", "+KC"}).name_digits, 2);
  // Clocks running backwards: +KFF4 +KI2 +KF-2 +KC gives 2, 1, 0, -1.
  const FramePlan back = plan({"+KFF4", "+KI2", "+KF-2", "+KC"});
  EXPECT_DOUBLE_EQ(back.frames[3].clock, -1.0);
  EXPECT_DOUBLE_EQ(back.frames[0].clock_delta, -1.0);
}

TEST(AnimationPlan, InitialFrameAndClockRange) {
  const FramePlan p = plan({"+KFI3", "+KFF12", "+KI2", "+KF4"});
  EXPECT_EQ(p.frames.size(), 10u);
  EXPECT_EQ(p.frames[0].frame_number, 3);
  EXPECT_DOUBLE_EQ(p.frames[0].clock, 2.0);
  EXPECT_NEAR(p.frames[1].clock, 2.222222, 1e-6);
  EXPECT_NEAR(p.frames[0].clock_delta, 0.222222, 1e-6);
  EXPECT_DOUBLE_EQ(p.frames[9].clock, 4.0);
  EXPECT_EQ(p.name_digits, 2);
  // +KFI alone: the final frame follows it (POV-Ray: frame 3 only).
  EXPECT_EQ(frame_numbers(plan({"+KFI3"})), (Frames{3}));
  // A negative initial frame is clamped to 0, as POV-Ray does.
  const FramePlan negative = plan({"+KFI-3", "+KFF3"});
  EXPECT_EQ(frame_numbers(negative), (Frames{0, 1, 2, 3}));
  EXPECT_NEAR(negative.frames[1].clock, 1.0 / 3.0, 1e-15);
  EXPECT_FALSE(negative.warnings.empty());
}

TEST(AnimationPlan, SubsetsByNumberAndByFraction) {
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "+SF3", "+EF5"})), (Frames{3, 4, 5}));
  EXPECT_NEAR(plan({"+KFF10", "+SF3"}).frames[0].clock, 0.222222, 1e-6);
  // Fractions: floor(fraction x frame count), not offset by the initial frame, then clamped.
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "+SF0.3", "+EF0.6"})), (Frames{3, 4, 5, 6}));
  EXPECT_EQ(frame_numbers(plan({"+KFI0", "+KFF10", "+SF0.3", "+EF0.6"})), (Frames{3, 4, 5, 6}));
  EXPECT_EQ(frame_numbers(plan({"+KFI5", "+KFF15", "+SF0.25", "+EF0.75"})), (Frames{5, 6, 7, 8}));
  EXPECT_EQ(frame_numbers(plan({"+KFI10", "+KFF30", "+SF0.5", "+EF0.9"})).back(), 18);
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "+SF0.5"})), (Frames{5, 6, 7, 8, 9, 10}));
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "+EF0.5"})), (Frames{1, 2, 3, 4, 5}));
  // 0 and 1 are frame numbers, not fractions.
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "+SF1.0", "+EF1.0"})), (Frames{1}));
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "+SF0", "+EF0"})), (Frames{1}));
  // With +KC the count includes the extra frame: +KFF10 +KC +SF0.5 +EF0.99 -> 5..10.
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "+KC", "+SF0.5", "+EF0.99"})),
            (Frames{5, 6, 7, 8, 9, 10}));
  EXPECT_EQ(frame_numbers(plan({"+KFI4", "+KFF10", "+KC", "+SF0.5", "+EF0.99"})),
            (Frames{4, 5, 6, 7}));
  EXPECT_NEAR(plan({"+KFI4", "+KFF10", "+KC", "+SF5"}).frames[0].clock, 0.142857, 1e-6);
}

TEST(AnimationPlan, FrameStepCountsFromTheSubsetStart) {
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "Frame_Step=3"})), (Frames{1, 4, 7, 10}));
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "+SF2", "Frame_Step=3"})), (Frames{2, 5, 8}));
  EXPECT_EQ(frame_numbers(plan({"+KFF10", "--frame-step", "4"})), (Frames{1, 5, 9}));
}

TEST(AnimationPlan, StillClockIsIgnoredByAnAnimation) {
  const FramePlan p = plan({"+KFF5", "+K0.3"});
  EXPECT_DOUBLE_EQ(p.frames[1].clock, 0.25);
}

// Ten million frames (the most one run renders) are computed as they are asked for: the plan
// is a few numbers, and its frames are POV-Ray's (clock = (n - 1) / (10^7 - 1), every third
// frame with Frame_Step=3).
TEST(AnimationPlan, TenMillionFramesWithoutAList) {
  const FramePlan p = plan({"+KFF10000000"});
  ASSERT_EQ(p.frames.size(), 10'000'000u);
  EXPECT_LT(sizeof(FramePlan), 512u);
  EXPECT_EQ(p.frames[9'999'999].frame_number, 10'000'000);
  EXPECT_EQ(p.frames[9'999'999].clock, 1.0);
  EXPECT_DOUBLE_EQ(p.frames[4'999'999].clock, 4'999'999.0 / 9'999'999.0);
  EXPECT_EQ(p.frames[0].clock, 0.0);
  const FramePlan stepped = plan({"+KFF10000000", "Frame_Step=3"});
  EXPECT_EQ(stepped.frames.size(), 3'333'334u);  // 1, 4, ..., 10^7
  EXPECT_EQ(stepped.frames[3'333'333].frame_number, 10'000'000);
}

TEST(AnimationPlan, WhereWeDifferFromPovRaysDefects) {
  // One frame: POV-Ray's clock is NaN; ours is the initial clock.
  FramePlan one = plan({"+KFF1", "+KI0.5"});
  ASSERT_EQ(one.frames.size(), 1u);
  EXPECT_EQ(one.frames[0].clock, 0.5);
  EXPECT_EQ(one.frames[0].clock_delta, 0.0);
  // A subset past the end is clamped (POV-Ray renders frames 11..20 with a clock past 1).
  const FramePlan past = plan({"+KFF10", "+SF8", "+EF20"});
  EXPECT_EQ(frame_numbers(past), (Frames{8, 9, 10}));
  EXPECT_EQ(past.warnings.size(), 1u);
  // Backwards ranges are errors (POV-Ray renders one frame, clock NaN for the first).
  EXPECT_THROW(plan({"+KFI5", "+KFF2"}), UsageError);
  EXPECT_THROW(plan({"+KFF10", "+SF7", "+EF3"}), UsageError);
  EXPECT_THROW(plan({"+KFF10", "+SF2.5"}), UsageError);
  EXPECT_THROW(plan({"+KFF10", "Frame_Step=0"}), UsageError);
}

TEST(FrameNames, PovRaysNumbering) {
  EXPECT_EQ(resolve_output("", "dir/walk.pov"), "walk.png");
  EXPECT_EQ(resolve_output("out/", "dir/walk.pov"), "out/walk.png");
  EXPECT_EQ(resolve_output("foo", "walk.pov"), "foo.png");
  EXPECT_EQ(resolve_output("foo.exr", "walk.pov"), "foo.exr");
  EXPECT_EQ(frame_file_name("out/walk.png", 7, 2), "out/walk07.png");
  EXPECT_EQ(frame_file_name("walk.png", 7, 1), "walk7.png");
  EXPECT_EQ(frame_file_name("foo.bar.png", 12, 2), "foo.bar12.png");
  EXPECT_EQ(frame_file_name("c.png", 99, 3), "c099.png");
  EXPECT_EQ(frame_file_name("run.d/c.png", 100, 3), "run.d/c100.png");
  EXPECT_TRUE(names_folder("x/"));
  EXPECT_FALSE(names_folder("x.png"));
}

class IniTest : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream((dir_ / name).string(), std::ios::binary) << text;
    return (dir_ / name).string();
  }
  std::string error_of(const std::vector<std::string>& args) {
    try {
      parse_render_arguments(args);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(no error)";
  }
  convray::testing::TestFolder folder_{"ini"};
  const std::filesystem::path& dir_ = folder_.path();
};

TEST_F(IniTest, KeysSwitchesCommentsAndQuotes) {
  const std::string ini = write("a.ini",
                                "; an animation\n"
                                "Input_File_Name=\"walk.pov\"   ; trailing comment\n"
                                "  width = 320 // also a comment\n"
                                "Height=240\n"
                                "+A0.2 +R4 -D\n"
                                "Final_Frame=\"4\"\n"
                                "CYCLIC_animation=yes\n"
                                "Declare=Speed=2.5\n"
                                "Library_Path=models\n"
                                "Output_File_Name=frames/\n");
  const RenderOptions o = parse_render_arguments({ini});
  EXPECT_EQ(o.scene, "walk.pov");
  EXPECT_EQ(o.width, 320);
  EXPECT_EQ(o.height, 240);
  EXPECT_TRUE(o.antialias);
  EXPECT_DOUBLE_EQ(o.aa_threshold, 0.2);
  EXPECT_EQ(o.aa_depth, 4);
  EXPECT_EQ(o.animation.final_frame, 4);
  EXPECT_TRUE(o.animation.cyclic);
  ASSERT_EQ(o.declares.size(), 1u);
  EXPECT_DOUBLE_EQ(o.declares[0].second, 2.5);
  EXPECT_EQ(o.library_paths, std::vector<std::string>{"models"});
  EXPECT_EQ(o.output, "frames/walk.png");
  EXPECT_TRUE(o.output_is_folder);
}

TEST_F(IniTest, SectionsAsPovRayReadsThem) {
  const std::string ini = write("s.ini",
                                "Final_Frame=3\n"
                                "[Long]\nFinal_Frame=12\nInitial_Clock=1\n"
                                "[Short]\nFinal_Frame=2\n+KF5\n"
                                "[long]\nFinal_Clock=7\n");
  // No section: up to the first one.
  RenderOptions o = parse_render_arguments({"c.pov", ini});
  EXPECT_EQ(o.animation.final_frame, 3);
  EXPECT_EQ(o.animation.initial_clock, 0.0);
  // A section: the common part, then every block of that name, any case.
  o = parse_render_arguments({"c.pov", ini + "[LONG]"});
  EXPECT_EQ(o.animation.final_frame, 12);
  EXPECT_EQ(o.animation.initial_clock, 1.0);
  EXPECT_EQ(o.animation.final_clock, 7.0);
  o = parse_render_arguments({"c.pov", ini + "[short]"});
  EXPECT_EQ(o.animation.final_frame, 2);
  EXPECT_EQ(o.animation.final_clock, 5.0);
  // Later arguments override the file's settings, earlier ones are overridden by it.
  o = parse_render_arguments({"c.pov", "+KFF9", ini, "+KFF20"});
  EXPECT_EQ(o.animation.final_frame, 20);
}

TEST_F(IniTest, IncludeIniReadsAnotherFileInPlace) {
  write("common.ini", "Width=111\nHeight=99\n");
  const std::string ini = write("main.ini", "Include_INI=common.ini\nHeight=77\n");
  const RenderOptions o = parse_render_arguments({"c.pov", ini});
  EXPECT_EQ(o.width, 111);
  EXPECT_EQ(o.height, 77);
  const std::string loop = write("loop.ini", "Include_INI=loop.ini\n");
  EXPECT_NE(error_of({"c.pov", loop}).find("includes itself"), std::string::npos);
}

TEST_F(IniTest, ErrorsPointAtFileLineAndColumn) {
  const std::string bad_value = write("v.ini", "Width=320\n  Height = abc\n");
  EXPECT_EQ(error_of({"c.pov", bad_value}),
            bad_value + ":2:12: Height: expected a number, got 'abc'");
  const std::string misspelt = write("k.ini", "Final_Fram=3\n");
  EXPECT_EQ(error_of({"c.pov", misspelt}),
            misspelt + ":1:1: unknown INI key 'Final_Fram'; did you mean Final_Frame?");
  const std::string no_equals = write("n.ini", "Width 320\n");
  EXPECT_NE(error_of({"c.pov", no_equals}).find(no_equals + ":1:1: expected Key=value"),
            std::string::npos);
  const std::string bad_switch = write("w.ini", "+W320 +Zq\n");
  EXPECT_EQ(error_of({"c.pov", bad_switch}),
            bad_switch + ":1:7: unknown switch '+Zq'; run 'convray --help' for the supported ones");
  const std::string open_quote = write("q.ini", "Input_File_Name=\"walk.pov\n");
  EXPECT_NE(error_of({open_quote}).find(":1:17: this quote is never closed"), std::string::npos);
  const std::string bad_bool = write("b.ini", "Cyclic_Animation=perhaps\n");
  EXPECT_NE(error_of({"c.pov", bad_bool}).find(":1:18: Cyclic_Animation: expected on or off"),
            std::string::npos);
  const std::string sections = write("sec.ini", "Width=3\n[A]\nWidth=4\n");
  EXPECT_NE(error_of({"c.pov", sections + "[B]"}).find("has no section [B]"), std::string::npos);
  EXPECT_NE(error_of({"c.pov", (dir_ / "missing.ini").string()}).find("cannot open INI file"),
            std::string::npos);
  const std::string binary = write("bin.ini", std::string("Width=3\0\1", 9));
  EXPECT_NE(error_of({"c.pov", binary}).find("not a text file"), std::string::npos);
}

TEST_F(IniTest, IniArgumentsAreRecognisedByTheirExtension) {
  EXPECT_TRUE(is_ini_argument("walk.ini"));
  EXPECT_TRUE(is_ini_argument("dir/WALK.INI[Fast]"));
  EXPECT_FALSE(is_ini_argument("walk.pov"));
  EXPECT_FALSE(is_ini_argument(".ini"));
  const IniArgument a = split_ini_argument("a/b.ini[Fast Run]");
  EXPECT_EQ(a.path, "a/b.ini");
  EXPECT_EQ(a.section, "Fast Run");
}

}  // namespace
}  // namespace convray::app
