// #declare #local #undef #version #debug #warning #error #default, and arrays.
#include <gtest/gtest.h>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::declared;
using core_testing::eval_float;
using core_testing::global_float;
using core_testing::global_string;
using core_testing::run;
using core_testing::scene_error;

TEST(Directives, DeclareFloatsVectorsColorsStrings) {
  const ParseResult result =
      run("#declare F = 1.5;\n"
          "#declare V = <1, 2, 3>;\n"
          "#declare C = rgb <1, 0, 0>;\n"
          "#declare S = \"text\";\n"
          "#declare G = F * 2;\n");
  EXPECT_EQ(global_float(result, "F"), 1.5);
  EXPECT_EQ(global_float(result, "G"), 3.0);
  EXPECT_EQ(global_string(result, "S"), "text");
  const Vector* v = result.globals.at("V").get<Vector>();
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->xyz(), Vec3(1, 2, 3));
  const Vector* c = result.globals.at("C").get<Vector>();
  ASSERT_NE(c, nullptr);
  EXPECT_TRUE(c->color);
  EXPECT_EQ(result.globals.at("F").loc.str(), "test.pov:1:10");
}

TEST(Directives, SemicolonsAreOptional) {
  // Without ';' the next directive must not run before the value is stored.
  const ParseResult result =
      run("#declare A = 1\n#declare B = A + 1\n#local C = <1, 2, 3>\n"
          "#declare D = C.y #declare E = D * 2");
  EXPECT_EQ(global_float(result, "A"), 1.0);
  EXPECT_EQ(global_float(result, "B"), 2.0);
  EXPECT_EQ(global_float(result, "E"), 4.0);
}

TEST(Directives, EmptyScenes) {
  EXPECT_TRUE(run("").scene.objects.empty());
  EXPECT_TRUE(run("// nothing\n/* at all */\n").globals.empty());
}

TEST(Directives, DirectivesBetweenStatements) {
  const ParseResult result =
      run("#declare R = 2;\n"
          "sphere { 0, R }\n"
          "#for (I, 1, 3) sphere { <I, 0, 0>, R / I } #end\n"
          "#if (R > 1) box { -1, 1 } #end\n");
  EXPECT_EQ(result.scene.objects.size(), 5u);
  const auto* ball = std::get_if<scene::Sphere>(&result.scene.objects[3]->shape);
  ASSERT_NE(ball, nullptr);
  EXPECT_EQ(ball->center, Vec3(3, 0, 0));
  EXPECT_DOUBLE_EQ(ball->radius, 2.0 / 3.0);
}

TEST(Directives, GlobalsHoldItemsToo) {
  const ParseResult result =
      run("#declare Ball = sphere { 0, 1 }\n#declare T = texture { "
          "pigment { rgb 1 } }\n");
  EXPECT_NE(result.globals.at("Ball").get<scene::ObjectPtr>(), nullptr);
  EXPECT_NE(result.globals.at("T").get<std::shared_ptr<const scene::Texture>>(), nullptr);
}

TEST(Directives, RedeclaringReplaces) {
  EXPECT_EQ(declared("#declare A = 1; #declare A = A + 1; #declare A = A * 10;", "A"), 20.0);
  EXPECT_EQ(declared("#declare A = 1; #declare A = \"now a string\"; #declare B = strlen(A);", "B"),
            12.0);
}

TEST(Directives, LocalInTheMainFileIsGlobal) { EXPECT_EQ(declared("#local A = 4;", "A"), 4.0); }

TEST(Directives, Undef) {
  const ParseResult result = run("#declare A = 1; #declare B = 2; #undef A");
  EXPECT_EQ(result.globals.count("A"), 0u);
  EXPECT_EQ(result.globals.count("B"), 1u);
  EXPECT_EQ(declared("#declare A = 1; #undef A #ifdef (A) #declare R = 1; #else #declare R = 0; "
                     "#end",
                     "R"),
            0.0);
}

TEST(Directives, UndefOfAnUndeclaredNameWarns) {
  const ParseResult result = run("#undef Nothing\n#version 3.7;");  // 3.7: no gamma warning
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].substr(0, result.warnings[0].find('\n')),
            "test.pov:1:8: #undef of 'Nothing', which is not declared");
}

TEST(Directives, VersionIsParsedAndRemembered) {
  EXPECT_EQ(declared("#version 3.5; #declare V = version;", "V"), 3.5);
  EXPECT_EQ(
      declared("#declare Old = version; #version 3.1; #version Old; #declare V = version;", "V"),
      3.7);
}

TEST(Directives, DebugAndWarningGoToWarnings) {
  const ParseResult result =
      run("#debug \"plain text\\n\"\n"
          "#declare N = 3;\n"
          "#warning concat(\"N is \", str(N, 0, 0))\n#version 3.7;\n");
  ASSERT_EQ(result.warnings.size(), 2u);
  EXPECT_EQ(result.warnings[0], "test.pov:1:1: #debug: plain text");
  EXPECT_EQ(result.warnings[1].substr(0, result.warnings[1].find('\n')), "test.pov:3:1: N is 3");
}

TEST(Directives, ErrorFailsAtItsLocation) {
  const core_testing::Failure failure =
      scene_error("#declare A = 1;\n  #error concat(\"bad \", \"thing\")\n");
  EXPECT_EQ(failure.first_line, "bad thing");
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 3);
  EXPECT_EQ(failure.message, "bad thing\n      #error concat(\"bad \", \"thing\")\n      ^");
}

TEST(Directives, DeprecatedIdentifiersWarnWhenUsed) {
  const ParseResult result =
      run("#declare deprecated once \"use New\" Old = 1;\n"
          "#declare A = Old + Old;\n#version 3.7;\n");
  EXPECT_EQ(global_float(result, "A"), 2.0);
  ASSERT_EQ(result.warnings.size(), 1u);  // once
  EXPECT_NE(result.warnings[0].find("test.pov:2:14: 'Old' is deprecated: use New"),
            std::string::npos);
}

TEST(Directives, DeprecatedItemsWarnOncePerUse) {
  const ParseResult result = run(
      "#declare deprecated \"use T2\" T1 = texture { pigment { rgb 1 } }\n"
      "sphere { 0, 1 texture { T1 } }\nsphere { 0, 1 texture { T1 } }\n");
  int count = 0;
  for (const std::string& warning : result.warnings) {
    count += warning.find("'T1' is deprecated: use T2") != std::string::npos;
  }
  EXPECT_EQ(count, 2);
}

TEST(Directives, DirectivesWorkBetweenAnyTokens) {
  EXPECT_EQ(eval_float("1 + #declare B = 2; B * #if (B > 1) 10 #else 20 #end"), 21.0);
}

TEST(Directives, DefaultSetsTheDefaultTexture) {
  Parser parser("test.pov",
                "#default { finish { ambient 0.3 diffuse 0.5 } }\n"
                "#default { pigment { color rgb <1, 0, 0> } }\n",
                {});
  parser.parse_scene();
  EXPECT_EQ(parser.defaults().texture.finish.diffuse, 0.5);
  EXPECT_EQ(parser.defaults().texture.finish.ambient, Vec3(0.3));
  EXPECT_EQ(parser.defaults().texture.pigment.color.rgb, Vec3(1, 0, 0));
}

TEST(Directives, DefaultTakesOnlyTextures) {
  const core_testing::Failure failure = scene_error("#default { 1 }");
  EXPECT_EQ(failure.first_line,
            "expected texture, pigment, finish or normal in #default, found '1'");
  EXPECT_EQ(failure.loc.column, 12);
}

// --- Arrays

TEST(Arrays, DeclareAssignAndRead) {
  const ParseResult result =
      run("#declare A = array[3];\n"
          "#declare A[0] = 10; #declare A[1] = 20; #declare A[2] = A[0] + A[1];\n"
          "#declare Sum = A[0] + A[1] + A[2];\n"
          "#declare Size = dimension_size(A, 1);\n"
          "#declare Dims = dimensions(A);\n");
  EXPECT_EQ(global_float(result, "Sum"), 60.0);
  EXPECT_EQ(global_float(result, "Size"), 3.0);
  EXPECT_EQ(global_float(result, "Dims"), 1.0);
}

TEST(Arrays, Initializers) {
  EXPECT_EQ(
      declared("#declare A = array[3] {1, 2, 3}; #declare R = A[0] * 100 + A[1] * 10 + A[2];", "R"),
      123.0);
  EXPECT_EQ(declared("#declare A = array[2][3] {{1, 2, 3}, {4, 5, 6}}; #declare R = A[1][2] * 10 + "
                     "A[0][1];",
                     "R"),
            62.0);
  EXPECT_EQ(
      declared("#declare A = array { 7, 8, 9, }; #declare R = dimension_size(A, 1) + A[2];", "R"),
      12.0);
  EXPECT_EQ(declared("#declare A = array mixed[2] {1, \"one\"}; #declare R = strlen(A[1]);", "R"),
            3.0);
  // Commas are optional, as POV-Ray's are.
  EXPECT_EQ(declared("#declare A = array[2][2] {{1 2} {3 4}}; #declare R = A[1][0];", "R"), 3.0);
  EXPECT_EQ(declared("#declare A = array {5 6 7}; #declare R = A[2];", "R"), 7.0);
  // Vectors and strings as elements.
  EXPECT_EQ(declared("#declare A = array[2] {<1, 2, 3>, <4, 5, 6>}; #declare R = A[1].y;", "R"),
            5.0);
}

TEST(Arrays, TwoDimensions) {
  const ParseResult result =
      run("#declare M = array[2][3];\n"
          "#for (I, 0, 1) #for (J, 0, 2) #declare M[I][J] = I * 10 + J; #end #end\n"
          "#declare R = M[1][2];\n"
          "#declare D = dimensions(M);\n"
          "#declare S2 = dimension_size(M, 2);\n");
  EXPECT_EQ(global_float(result, "R"), 12.0);
  EXPECT_EQ(global_float(result, "D"), 2.0);
  EXPECT_EQ(global_float(result, "S2"), 3.0);
}

TEST(Arrays, CopiesAreIndependent) {
  const ParseResult result =
      run("#declare A = array[2] {1, 2};\n"
          "#declare B = A;\n"
          "#declare B[0] = 100;\n"
          "#declare A0 = A[0]; #declare B0 = B[0];\n");
  EXPECT_EQ(global_float(result, "A0"), 1.0);
  EXPECT_EQ(global_float(result, "B0"), 100.0);
}

TEST(Arrays, ArraysOfArrays) {
  EXPECT_EQ(declared("#declare Inner = array[2] {5, 6}; #declare Outer = array[1] {Inner};"
                     "#declare Outer[0][1] = 60; #declare R = Outer[0][1] + Inner[1];",
                     "R"),
            66.0);
}

TEST(Arrays, IfdefOfAnElement) {
  EXPECT_EQ(declared("#declare A = array[2]; #declare A[1] = 1;"
                     "#declare R = 0; #ifdef (A[1]) #declare R = R + 1; #end"
                     "#ifndef (A[0]) #declare R = R + 10; #end",
                     "R"),
            11.0);
}

TEST(Arrays, Errors) {
  core_testing::Failure failure = scene_error("#declare A = array[3];\n#declare B = A[3];");
  EXPECT_EQ(failure.first_line, "array index 3 out of range: 'A' has 3 elements there (0 to 2)");
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 16);
  failure = scene_error("#declare A = array[3];\n#declare B = A[-1];");
  EXPECT_EQ(failure.first_line, "array index -1 out of range: 'A' has 3 elements there (0 to 2)");
  failure = scene_error("#declare A = array[3];\n#declare B = A[1];");
  EXPECT_EQ(failure.first_line, "an element of 'A' is read before it was given a value");
  EXPECT_EQ(failure.loc.column, 15);
  failure = scene_error("#declare A = array[3] {1, 2, 3, 4};");
  EXPECT_EQ(failure.first_line, "too many elements: array dimension 1 has 3");
  EXPECT_EQ(failure.loc.column, 33);
  failure = scene_error("#declare A = array[0];");
  EXPECT_EQ(failure.first_line, "an array size must be at least 1, found 0");
  failure = scene_error("#declare A = array[2][2]; #declare B = A[1];");
  EXPECT_EQ(failure.first_line, "'A' has 2 dimensions: expected '[' for index 2, found ';'");
  failure = scene_error("#declare A = 1; #declare A[0] = 2;");
  EXPECT_EQ(failure.first_line, "'A' is not an array");
  failure = scene_error("#declare A = array[100000][100000];");
  EXPECT_EQ(failure.first_line, "array too large (more than 2097152 elements)");
}

}  // namespace
}  // namespace convray::sdl
