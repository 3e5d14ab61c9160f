// One budget for what a scene holds (issue 21): the elements of every live array (an array of
// arrays counts every element of each), long strings held in arrays, and meshes built in the
// scene (their vertices, normals, textures and faces, and the copies `object { M modifiers }`
// makes). The expected failing element and count are worked out by hand from the rule.
#include <gtest/gtest.h>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::declared;
using core_testing::scene_error;

const std::string kMessage =
    "the scene's arrays, strings and meshes would hold more than 1000 elements in all (an "
    "array of arrays counts every element of each, a string in an array one more per 96 "
    "characters, a mesh one per vertex, normal, texture and face)";

ParseOptions budget_of_1000() {
  ParseOptions options = program_options();
  options.max_live_array_elements = 1000;
  return options;
}

// Arrays of arrays: the fourth array of 300 inside an array of 20 is refused where it is
// made; arrays no longer held give their elements back, and a copy (made when a shared array
// is written) holds them again.
TEST(ElementBudget, ArraysOfArraysCountEveryElement) {
  const ParseOptions options = budget_of_1000();
  const std::string outer = "#declare A = array[20];\n";
  core_testing::Failure failure =
      scene_error(outer + "#for (I, 0, 19)\n  #declare A[I] = array[300];\n#end\n", options);
  EXPECT_EQ(failure.first_line, kMessage);
  EXPECT_EQ(failure.loc.line, 3);
  EXPECT_EQ(failure.loc.column, 19);
  // 50 arrays of 400 made one after another, each replacing the last: at most two live.
  EXPECT_EQ(declared("#for (I, 1, 50) #declare B = array[400]; #end #declare N = "
                     "dimension_size(B, 1);",
                     "N", options),
            400.0);
  failure = scene_error(outer +
                            "#for (I, 0, 2) #declare A[I] = array[300]; #end\n"
                            "#declare B = A[0];\n#declare B[0] = 1;\n",
                        options);
  EXPECT_EQ(failure.loc.line, 4);  // 20 + 3 x 300 live; the copy of 300 would pass 1000
  EXPECT_EQ(declared(outer + "#for (I, 0, 2) #declare A[I] = array[300]; #end\n"
                             "#declare B = A[0];\n#declare N = dimension_size(B, 1);",
                     "N", options),
            300.0);  // shared, not copied: still within the budget
}

// A string of 960 characters in an array counts 1 + 960 / 96 = 11 elements.
TEST(ElementBudget, LongStringsInArraysCount) {
  const ParseOptions options = budget_of_1000();
  const std::string long_string = "#declare S = \"" + std::string(960, 'x') + "\";\n";
  // 100 elements + k x 10 more: the 91st string (I = 90) would make 1010, the 90th is within.
  core_testing::Failure failure = scene_error(
      long_string + "#declare A = array[100];\n#for (I, 0, 90)\n  #declare A[I] = S;\n#end\n",
      options);
  EXPECT_EQ(failure.first_line, kMessage);
  EXPECT_EQ(failure.loc.line, 4);
  EXPECT_EQ(declared(long_string + "#declare A = array[100];\n#for (I, 0, 89) #declare A[I] = S; "
                                   "#end\n#declare N = 1;",
                     "N", options),
            1.0);  // 100 + 90 x 10 = 1000: within
  // Writing a short string over a long one gives its characters back.
  EXPECT_EQ(declared(long_string + "#declare A = array[100];\n#for (I, 1, 500) #declare A[0] = S; "
                                   "#declare A[0] = \"\"; #end\n#declare N = 1;",
                     "N", options),
            1.0);
  // A list sized by its elements: 91 strings of 11 make 1001, refused at the 91st.
  std::string list = long_string + "#declare A = array {\n";
  for (int i = 0; i < 91; ++i) list += "S,\n";
  failure = scene_error(list + "}\n", options);
  EXPECT_EQ(failure.first_line, kMessage);
  EXPECT_EQ(failure.loc.line, 2 + 91);
  // An initializer counts its strings as well: 100 + 91 x 10.
  std::string initializer = long_string + "#declare A = array[100] {\n";
  for (int i = 0; i < 91; ++i) initializer += "S,\n";
  failure = scene_error(initializer + "}\n", options);
  EXPECT_EQ(failure.loc.line, 2 + 91);
}

std::string triangles(int count) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    text += "  triangle { <" + std::to_string(i) + ", 0, 0>, <" + std::to_string(i) + ", 1, 0>, <" +
            std::to_string(i) + ", 0, 1> }\n";
  }
  return text;
}

TEST(ElementBudget, MeshesCountTheirVerticesAndFaces) {
  const ParseOptions options = budget_of_1000();
  // A mesh triangle is 3 vertices and a face: the 251st of 300 would make 1004.
  core_testing::Failure failure = scene_error("mesh {\n" + triangles(300) + "}\n", options);
  EXPECT_EQ(failure.first_line, kMessage);
  EXPECT_EQ(failure.loc.line, 1 + 251);
  // mesh2's items count as they are read, not as declared: 1001 vertices are refused at the
  // 1001st; a count of 10^9 with three vertices behind it takes nothing.
  std::string vertices = "mesh2 {\n  vertex_vectors { 1001,\n";
  for (int i = 0; i < 1001; ++i) vertices += "    <" + std::to_string(i) + ", 0, 0>,\n";
  failure = scene_error(vertices + "  }\n}\n", options);
  EXPECT_EQ(failure.first_line, kMessage);
  EXPECT_EQ(failure.loc.line, 2 + 1001);
  failure = scene_error("mesh2 { vertex_vectors { 1000000000, 0, x, y } }", options);
  EXPECT_EQ(failure.first_line, "vertex_vectors says 1000000000 but lists 3");
}

TEST(ElementBudget, CopiesOfAMeshCountAgain) {
  const ParseOptions options = budget_of_1000();
  // 100 triangles: 400 elements. A second copy with a modifier would hold 1200.
  const std::string mesh = "#declare M = mesh {\n" + triangles(100) + "}\n";
  core_testing::Failure failure =
      scene_error(mesh + "object { M translate x }\nobject { M translate y }\n", options);
  EXPECT_EQ(failure.first_line, kMessage);
  EXPECT_EQ(failure.loc.line, 2 + 100 + 2);
  // Without modifiers the mesh is shared, not copied; a mesh no longer held gives its elements
  // back (50 meshes of 400 made one after another).
  EXPECT_EQ(
      declared(mesh + "object { M }\nobject { M }\nobject { M }\n#declare N = 1;", "N", options),
      1.0);
  EXPECT_EQ(
      declared("#for (I, 1, 50) #declare M = mesh {\n" + triangles(100) + "} #end #declare N = 1;",
               "N", options),
      1.0);
}

}  // namespace
}  // namespace convray::sdl
