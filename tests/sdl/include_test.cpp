// #include: search order, scopes, nesting limits, errors inside included files, and
// POV-Ray's own include files.
#include <gtest/gtest.h>

#include <filesystem>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::global_float;
using core_testing::TempFolder;

const char* kPovRayIncludes = "/usr/share/povray-3.7/include";

ParseResult parse_scene_file(const std::string& path, ParseOptions options = {}) {
  return parse_file(path, options);
}

core_testing::Failure file_error(const std::string& path, ParseOptions options = {}) {
  try {
    parse_file(path, options);
  } catch (const InputError& error) {
    return core_testing::to_failure(error);
  }
  ADD_FAILURE() << "expected an error from " << path;
  return {};
}

TEST(Include, FromTheScenesFolder) {
  TempFolder folder;
  folder.write("defs.inc", "#declare FromInclude = 42;\n#macro Twice(X) (2 * X) #end\n");
  const std::string scene =
      folder.write("scene.pov", "#include \"defs.inc\"\n#declare R = Twice(FromInclude);\n");
  const ParseResult result = parse_scene_file(scene);
  EXPECT_EQ(global_float(result, "FromInclude"), 42.0);
  EXPECT_EQ(global_float(result, "R"), 84.0);
}

TEST(Include, NestedIncludesSearchTheIncludingFilesFolder) {
  TempFolder folder;
  folder.write("lib/outer.inc", "#include \"inner.inc\"\n#declare Outer = Inner + 1;\n");
  folder.write("lib/inner.inc", "#declare Inner = 10;\n");
  const std::string scene = folder.write("scene.pov", "#include \"lib/outer.inc\"\n");
  EXPECT_EQ(global_float(parse_scene_file(scene), "Outer"), 11.0);
}

TEST(Include, LibraryPaths) {
  TempFolder folder;
  folder.write("library/shared.inc", "#declare Shared = 7;\n");
  const std::string scene = folder.write("scenes/scene.pov", "#include \"shared.inc\"\n");
  ParseOptions options;
  options.library_paths = {folder.path() + "/library"};
  EXPECT_EQ(global_float(parse_scene_file(scene, options), "Shared"), 7.0);
}

TEST(Include, StringExpressionsNameTheFile) {
  TempFolder folder;
  folder.write("part2.inc", "#declare Part = 2;\n");
  const std::string scene = folder.write(
      "scene.pov", "#declare N = 2;\n#include concat(\"part\", str(N, 0, 0), \".inc\")\n");
  EXPECT_EQ(global_float(parse_scene_file(scene), "Part"), 2.0);
}

TEST(Include, LocalsOfAnIncludeFileStayInIt) {
  TempFolder folder;
  folder.write("locals.inc", "#local Hidden = 5;\n#declare Visible = Hidden + A;\n");
  const std::string scene = folder.write(
      "scene.pov", "#declare A = 1;\n#declare Hidden = 100;\n#include \"locals.inc\"\n");
  const ParseResult result = parse_scene_file(scene);
  EXPECT_EQ(global_float(result, "Visible"), 6.0);
  EXPECT_EQ(global_float(result, "Hidden"), 100.0);
}

TEST(Include, GuardsAndRepeatedIncludes) {
  TempFolder folder;
  folder.write("guarded.inc",
               "#ifndef (Guarded_Inc) #declare Guarded_Inc = 1;\n"
               "#declare Count = Count + 1;\n#end\n");
  folder.write("counter.inc", "#declare Times = Times + 1;\n");
  const std::string scene = folder.write("scene.pov",
                                         "#declare Count = 0; #declare Times = 0;\n"
                                         "#include \"guarded.inc\" #include \"guarded.inc\"\n"
                                         "#for (I, 1, 3) #include \"counter.inc\" #end\n");
  const ParseResult result = parse_scene_file(scene);
  EXPECT_EQ(global_float(result, "Count"), 1.0);
  EXPECT_EQ(global_float(result, "Times"), 3.0);
}

TEST(Include, InsideAnItem) {
  TempFolder folder;
  folder.write("red.inc", "pigment { color rgb <1, 0, 0> }\n");
  const std::string scene = folder.write("scene.pov", "sphere { 0, 1 #include \"red.inc\" }\n");
  const ParseResult result = parse_scene_file(scene);
  ASSERT_EQ(result.scene.objects.size(), 1u);
  EXPECT_EQ(result.scene.objects[0]->texture->pigment.color.rgb, Vec3(1, 0, 0));
}

TEST(Include, FileNotFound) {
  TempFolder folder;
  const std::string scene =
      folder.write("scene.pov", "#declare A = 1;\n  #include \"missing.inc\"\n");
  ParseOptions options;
  options.system_include_paths = {};
  const core_testing::Failure failure = file_error(scene, options);
  EXPECT_EQ(failure.first_line.substr(0, failure.first_line.find(" (searched")),
            "file not found: 'missing.inc'");
  EXPECT_EQ(failure.loc.file, scene);
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 12);
}

TEST(Include, ErrorsInsideAnIncludedFilePointIntoIt) {
  TempFolder folder;
  const std::string bad = folder.write("bad.inc", "#declare A = 1;\n#declare B = A / 0;\n");
  const std::string scene = folder.write("scene.pov", "#include \"bad.inc\"\n");
  const core_testing::Failure failure = file_error(scene);
  EXPECT_EQ(failure.loc.file, bad);
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 16);
  EXPECT_EQ(failure.message, "division by zero\n    #declare B = A / 0;\n                   ^");

  const std::string unterminated = folder.write("open.inc", "#if (1)\n#declare C = 1;\n");
  const std::string scene2 = folder.write("scene2.pov", "#include \"open.inc\"\n#end\n");
  const core_testing::Failure open = file_error(scene2);
  EXPECT_EQ(open.loc.file, unterminated);
  EXPECT_EQ(open.first_line,
            "unterminated #if (opened at 1:1): expected #end before the end of the file");

  const std::string lexical = folder.write("lex.inc", "#declare S = \"no end\n");
  const std::string scene3 = folder.write("scene3.pov", "#include \"lex.inc\"\n");
  const core_testing::Failure lex = file_error(scene3);
  EXPECT_EQ(lex.loc.file, lexical);
  EXPECT_EQ(lex.loc.column, 14);
}

TEST(Include, DepthIsLimited) {
  TempFolder folder;
  const std::string scene = folder.write("self.pov", "#declare N = 0;\n#include \"self.inc\"\n");
  const std::string self = folder.write("self.inc", "#declare N = N + 1;\n#include \"self.inc\"\n");
  ParseOptions options;
  options.max_include_depth = 20;
  const core_testing::Failure failure = file_error(scene, options);
  EXPECT_EQ(failure.first_line,
            "#include nested more than 20 levels deep (does a file include itself?)");
  EXPECT_EQ(failure.loc.file, self);
  EXPECT_EQ(failure.loc.line, 2);
}

TEST(Include, TheSceneFileMustExist) {
  const core_testing::Failure failure = file_error("/nonexistent/scene.pov");
  EXPECT_EQ(failure.first_line, "cannot read the scene file");
  EXPECT_EQ(failure.loc.file, "/nonexistent/scene.pov");
}

TEST(Include, FileExists) {
  TempFolder folder;
  folder.write("here.inc", "");
  const std::string scene = folder.write("scene.pov",
                                         "#declare Yes = file_exists(\"here.inc\");\n"
                                         "#declare No = file_exists(\"not_here.inc\");\n");
  const ParseResult result = parse_scene_file(scene);
  EXPECT_EQ(global_float(result, "Yes"), 1.0);
  EXPECT_EQ(global_float(result, "No"), 0.0);
}

// --- POV-Ray's include files

TEST(PovRayIncludes, ColorsInc) {
  if (!std::filesystem::exists(std::string(kPovRayIncludes) + "/colors.inc")) {
    GTEST_SKIP() << "POV-Ray's include files are not installed";
  }
  const ParseResult result = core_testing::run(
      "#include \"colors.inc\"\n"
      "sphere { 0, 1 pigment { color Red } }\n"
      "#declare G = Gray50.red;\n"
      "#declare Hue = CHSV2RGB(<120, 1, 1>);\n"
      "#declare Back = CRGB2HSV(rgb <0, 1, 0>);\n"
      "#declare V = version;\n");
  ASSERT_EQ(result.scene.objects.size(), 1u);
  EXPECT_EQ(result.scene.objects[0]->texture->pigment.color.rgb, Vec3(1, 0, 0));
  EXPECT_DOUBLE_EQ(global_float(result, "G"), 0.5);
  const Vector* hue = result.globals.at("Hue").get<Vector>();
  ASSERT_NE(hue, nullptr);
  EXPECT_EQ(hue->xyz(), Vec3(0, 1, 0));
  const Vector* back = result.globals.at("Back").get<Vector>();
  ASSERT_NE(back, nullptr);
  EXPECT_EQ(back->xyz(), Vec3(120, 1, 1));
  EXPECT_EQ(global_float(result, "V"), 3.7);  // colors.inc restores the version it changed
  EXPECT_NE(result.globals.find("Colors_Inc_Temp"), result.globals.end());
}

TEST(PovRayIncludes, MathAndFriendsParse) {
  if (!std::filesystem::exists(std::string(kPovRayIncludes) + "/math.inc")) {
    GTEST_SKIP() << "POV-Ray's include files are not installed";
  }
  // Directives, macros, arrays and user functions of the core, with few items.
  const ParseResult result = core_testing::run(
      "#include \"math.inc\"\n#include \"strings.inc\"\n#include \"consts.inc\"\n"
      "#include \"transforms.inc\"\n#include \"rand.inc\"\n#include \"arrays.inc\"\n"
      "#declare S = sind(30);\n#declare E = even(4);\n");
  EXPECT_NEAR(global_float(result, "S"), 0.5, 1e-15);
  EXPECT_EQ(global_float(result, "E"), 1.0);
}

TEST(PovRayIncludes, MissingWithoutTheSystemPath) {
  ParseOptions options;
  options.system_include_paths = {};
  const core_testing::Failure failure =
      core_testing::scene_error("#include \"colors.inc\"", options);
  EXPECT_EQ(failure.first_line.substr(0, 30), "file not found: 'colors.inc' (");
}

}  // namespace
}  // namespace convray::sdl
