// The render command's arguments: POV-Ray's switches as POV-Ray's documentation defines them
// (+W800, +A0.3, -A, +R3, +J, +WT2, +L, Declare=), our long options, and their errors.
#include "app/render_options.hpp"

#include <gtest/gtest.h>

namespace convray::app {
namespace {

RenderOptions parse(std::vector<std::string> args) { return parse_render_arguments(args); }

std::string error_of(std::vector<std::string> args) {
  try {
    parse_render_arguments(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(RenderOptions, PovRaySwitchesAsTheIssueWritesThem) {
  const RenderOptions o =
      parse({"+Iscene.pov", "+Oout.png", "+W640", "+H480", "+A0.3", "-D", "+WT2"});
  EXPECT_EQ(o.scene, "scene.pov");
  EXPECT_EQ(o.output, "out.png");
  EXPECT_EQ(o.width, 640);
  EXPECT_EQ(o.height, 480);
  EXPECT_TRUE(o.antialias);
  EXPECT_DOUBLE_EQ(o.aa_threshold, 0.3);
  EXPECT_EQ(o.threads, 2);
}

TEST(RenderOptions, DefaultsFollowPovRay) {
  const RenderOptions o = parse({"dir/blob.pov"});
  EXPECT_EQ(o.output, "blob.png");  // the scene's name, in the current folder
  EXPECT_EQ(o.width, 800);
  EXPECT_EQ(o.height, 600);
  EXPECT_FALSE(o.antialias);
  EXPECT_EQ(o.aa_depth, 3);
  EXPECT_EQ(o.threads, 0);
}

TEST(RenderOptions, SwitchesAreCaseInsensitiveAndSignsMatter) {
  RenderOptions o = parse({"s.pov", "+a", "+r4", "+j0.5", "+w10", "+h20"});
  EXPECT_TRUE(o.antialias);
  EXPECT_DOUBLE_EQ(o.aa_threshold, 0.3);
  EXPECT_EQ(o.aa_depth, 4);
  EXPECT_TRUE(o.jitter);
  EXPECT_DOUBLE_EQ(o.jitter_amount, 0.5);
  EXPECT_EQ(o.width, 10);
  o = parse({"s.pov", "+A0.1", "-A", "+J", "-J"});
  EXPECT_FALSE(o.antialias);
  EXPECT_FALSE(o.jitter);
  EXPECT_FALSE(parse({"s.pov", "+J0"}).jitter);  // +J0 turns jitter off
}

TEST(RenderOptions, LongOptionsAndPovRaySwitchesMix) {
  const RenderOptions o = parse({"--width", "32", "+H24", "s.pov", "-o", "a.exr", "--antialias",
                                 "0.2", "--threads=3", "-L", "inc", "+Lmore", "--declare",
                                 "Speed=2.5", "Declare=N=3", "--stats", "+K0.25"});
  EXPECT_EQ(o.width, 32);
  EXPECT_EQ(o.height, 24);
  EXPECT_EQ(o.output, "a.exr");
  EXPECT_DOUBLE_EQ(o.aa_threshold, 0.2);
  EXPECT_EQ(o.threads, 3);
  ASSERT_EQ(o.library_paths.size(), 2u);
  EXPECT_EQ(o.library_paths[1], "more");
  ASSERT_EQ(o.declares.size(), 2u);
  EXPECT_EQ(o.declares[0].first, "Speed");
  EXPECT_DOUBLE_EQ(o.declares[0].second, 2.5);
  EXPECT_EQ(o.declares[1].first, "N");
  EXPECT_TRUE(o.stats);
  ASSERT_TRUE(o.animation.clock.has_value());
  EXPECT_DOUBLE_EQ(*o.animation.clock, 0.25);
}

// POV-Ray 3.7 reads a switch that carries a value the same after '-' as after '+'
// (`povray -Is.pov -W32 -H24 -Oa.png -Linc -R3` renders a.png at 32x24 with inc/ searched).
TEST(RenderOptions, ValueSwitchesReadTheSameAfterAMinus) {
  const RenderOptions minus =
      parse({"-Is.pov", "-W32", "-H24", "-Oa.png", "-Linc", "-R4", "-K0.5", "-KFF9", "-SF2"});
  const RenderOptions plus =
      parse({"+Is.pov", "+W32", "+H24", "+Oa.png", "+Linc", "+R4", "+K0.5", "+KFF9", "+SF2"});
  EXPECT_EQ(minus.scene, plus.scene);
  EXPECT_EQ(minus.width, 32);
  EXPECT_EQ(minus.height, 24);
  EXPECT_EQ(minus.output, plus.output);
  EXPECT_EQ(minus.library_paths, plus.library_paths);
  EXPECT_EQ(minus.aa_depth, 4);
  ASSERT_TRUE(minus.animation.clock.has_value());
  EXPECT_DOUBLE_EQ(*minus.animation.clock, 0.5);
  EXPECT_EQ(minus.animation.final_frame, plus.animation.final_frame);
  EXPECT_EQ(minus.animation.subset_start, plus.animation.subset_start);
  // Without a value, '-' keeps its meaning of "off" where it has one, and +A/-A still toggle.
  EXPECT_FALSE(parse({"s.pov", "+A", "-A"}).antialias);
}

TEST(RenderOptions, ConsoleSwitchesPovRayUsersPassAreAccepted) {
  EXPECT_NO_THROW(parse({"s.pov", "+D", "-D", "-V", "+P", "-GA", "+Q9", "+FN"}));
}

TEST(RenderOptions, DisplayAndPauseAsPovRaySpellsThem) {
  EXPECT_FALSE(parse({"s.pov"}).display);
  EXPECT_FALSE(parse({"s.pov"}).pause_when_done);
  EXPECT_TRUE(parse({"s.pov", "+D"}).display);
  EXPECT_TRUE(parse({"s.pov", "+d"}).display);
  EXPECT_TRUE(parse({"s.pov", "+D0"}).display);  // POV-Ray's +Dxy: display type and palette
  EXPECT_FALSE(parse({"s.pov", "+D", "-D"}).display);
  EXPECT_TRUE(parse({"s.pov", "--display"}).display);
  EXPECT_TRUE(parse({"s.pov", "Display=on"}).display);
  EXPECT_FALSE(parse({"s.pov", "+D", "Display=off"}).display);
  EXPECT_TRUE(parse({"s.pov", "+P"}).pause_when_done);
  EXPECT_FALSE(parse({"s.pov", "+P", "-P"}).pause_when_done);
  EXPECT_TRUE(parse({"s.pov", "--pause"}).pause_when_done);
  EXPECT_TRUE(parse({"s.pov", "Pause_When_Done=true"}).pause_when_done);
  EXPECT_NE(error_of({"s.pov", "Display=maybe"}).find("Display"), std::string::npos);
}

TEST(RenderOptions, BadArgumentsAreNamed) {
  EXPECT_NE(error_of({}).find("no scene file given"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "+W0"}).find("+W0"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "+Wabc"}).find("+Wabc: expected a number"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "+H1.5"}).find("+H1.5"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "+Zzz"}).find("unknown switch '+Zzz'"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "--frobnicate"}).find("unknown option '--frobnicate'"),
            std::string::npos);
  EXPECT_NE(error_of({"a.pov", "b.pov"}).find("one scene at a time"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "--width"}).find("expected a value"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "Declare=1x=2"}).find("expected ID=VALUE"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "+A-1"}).find(">= 0"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "+R0"}).find("+R0"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "+I"}).find("expected the scene file"), std::string::npos);
  EXPECT_NE(error_of({"s.pov", "+AM2"}).find("method 1"), std::string::npos);
}

}  // namespace
}  // namespace convray::app
