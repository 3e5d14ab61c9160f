// Inputs the fuzzer (fuzz/mesh_fuzz.cpp) once found a bug with, cut down to the point.
// Each must end in a clean InputError or a clean load, never in a crash, a leak or undefined
// behaviour; run the suite under CONVRAY_SANITIZE=ON to check the last two.
#include <gtest/gtest.h>

#include "mesh/load.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

using testing::input_error_of;

const std::string kTriangleStl =
    "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
    "  endloop\n endfacet\nendsolid t\n";

TEST(FuzzRegression, ObjSkinWeightOutOfIntRange) {
  // tinyobjloader (our OBJ reader then) converted the joint id to int without a range check
  // (UB). Our own reader skips `vw` lines.
  LoadedMesh mesh = load_mesh_from_memory("v 0 0 0\nvw 1 5257311121191336 -0.85\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "w.obj");
  EXPECT_EQ(mesh.soup.size(), 1u);
}

TEST(FuzzRegression, AsciiStlThatAssimpGivesUpOnLeaked) {
  // assimp's ASCII STL reader (our STL reader then) leaked its meshes whenever it threw; here
  // it threw because it reads a vertex's numbers skipping blanks only, not line ends. Ours
  // wants the numbers on the keyword's line too.
  std::string stl = kTriangleStl;
  stl.replace(stl.find("vertex 1 0 0"), 12, "vertex\r1 0 0");
  EXPECT_EQ(input_error_of([&] { load_mesh_from_memory(stl, "cr.stl"); }),
            "cr.stl:5: ASCII STL: expected three numbers on the line (face 0)");
}

TEST(FuzzRegression, PlyFacesMissingAfterALastLineWithoutLineEnd) {
  // The plain face-line shortcut (AsciiPlyBody::read_plain_list) then started one past the
  // end of the body and read on from there.
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 3\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0";
  EXPECT_EQ(input_error_of([&] { load_mesh_from_memory(ply, "end.ply"); }),
            "end.ply: the file ends before all data: the header declares 3 face elements (the file is truncated) "
            "(face 2)");
}

TEST(FuzzRegression, AsciiStlNumberAssimpCannotParse) {
  std::string stl = kTriangleStl;
  stl.replace(stl.find("vertex 1 0 0"), 12, "vertex 1 0 nan(7)");
  EXPECT_EQ(input_error_of([&] { load_mesh_from_memory(stl, "nan.stl"); }),
            "nan.stl:5: ASCII STL: expected a number but found 'nan(7)' (face 0)");
}

TEST(FuzzRegression, AsciiStlKeywordInTheSolidName) {
  std::string stl = kTriangleStl;
  stl.replace(0, 7, "solid my vertex");
  EXPECT_EQ(input_error_of([&] { load_mesh_from_memory(stl, "name.stl"); }),
            "name.stl:1: ASCII STL: the solid's name contains the keyword 'vertex'");
}

TEST(FuzzRegression, AsciiStlWithSeveralSolids) {
  LoadedMesh mesh = load_mesh_from_memory("\n\n" + kTriangleStl + kTriangleStl, "two.stl");
  EXPECT_EQ(mesh.soup.size(), 2u);
  EXPECT_EQ(mesh.format, "STL ascii");
}

TEST(FuzzRegression, AsciiStlNumberWithTwoSigns) {
  // Our scanner took "+-.5" for -0.5 (it stripped the '+'); assimp threw on it and leaked.
  std::string stl = kTriangleStl;
  stl.replace(stl.find("vertex 1 0 0"), 12, "vertex 1 0 +-.5");
  EXPECT_EQ(input_error_of([&] { load_mesh_from_memory(stl, "signs.stl"); }),
            "signs.stl:5: ASCII STL: expected a number but found '+-.5' (face 0)");
}

TEST(FuzzRegression, PlyHeaderEndingWithoutLineEnd) {
  // "end_header" as the last bytes, with no line end: the body offset pointed one past the
  // data, and string_view::substr threw std::out_of_range (the process aborted).
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header";
  const std::string error = input_error_of([&] { load_mesh_from_memory(ply, "cut.ply"); });
  EXPECT_NE(error.find("cut.ply"), std::string::npos) << error;
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  EXPECT_NO_THROW((void)input_error_of([&] { load_mesh_from_memory(ply + " ", "cut.ply"); }));
}

}  // namespace
}  // namespace convray::mesh
