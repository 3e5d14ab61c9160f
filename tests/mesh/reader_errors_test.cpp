// The refusals of the readers that docs/mesh-input.md quotes and the other suites do not pin,
// each on a file small enough to see the fault in.
#include <gtest/gtest.h>

#include "mesh/load.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

std::string error_loading(const std::string& bytes, const std::string& name) {
  return testing::input_error_of([&] { load_mesh_from_memory(bytes, name); });
}

const std::string kVertices =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";

TEST(ReaderErrors, Ply) {
  EXPECT_EQ(error_loading(kVertices + "element face 1\nproperty list int int vertex_indices\nend_header\n"
                                      "0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n", "x.ply"),
            "x.ply:13: list 'vertex_indices' has a negative length (face 0)");
  EXPECT_EQ(error_loading(kVertices + "element edge 1\nproperty int vertex1\nend_header\n0 0 0\n1 0 0\n0 1 0\n0\n",
                          "x.ply"),
            "x.ply: the PLY edge element has no integer property 'vertex2'");
  EXPECT_EQ(error_loading(kVertices + "element face 1\nproperty list uchar uint vertex_indices\nend_header\n"
                                      "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "x.ply"),
            "x.ply:13: value '-1' of 'vertex_indices' is not a uint (face 0)");
  EXPECT_EQ(error_loading(kVertices + "end_header\n0 0 0\n1 abc 0\n0 1 0\n", "x.ply"),
            "x.ply:9: value 'abc' of 'y' is not a number (vertex 1)");
  EXPECT_EQ(error_loading(kVertices + "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                      "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "x.ply"),
            "x.ply:13: face has 2 corners; at least 3 are needed (face 0)");
  EXPECT_EQ(error_loading(kVertices + "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
                                      "0 0 0\n1 0 0\n0 1 0\n0 3\n", "x.ply"),
            "x.ply:14: edge refers to vertex 3, but the file has 3 vertices (edge 0)");
  EXPECT_EQ(error_loading(kVertices + "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                                      "0 0 0\n1 0 0\n0 1 0\n4 0 1 -1 7\n", "x.ply"),
            "x.ply:13: face refers to vertex 7, but the file has 3 vertices (tristrips 0)");
  EXPECT_EQ(error_loading("ply\nformat ascii 1.0\nformat ascii 1.0\n", "x.ply"),
            "x.ply:3: a second format line (the first is line 2)");
}

TEST(ReaderErrors, Obj) {
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2/3/4 2 3\n", "x.obj"),
            "x.obj:4: face corner '1/2/3/4' is not of the form v, v/vt, v//vn or v/vt/vn (face 0)");
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 0\nl 1\n", "x.obj"), "x.obj:3: line has 1 corner; at least 2 are needed (line 0)");
  EXPECT_EQ(error_loading("v 0 0 0\nl 1//1 1\n", "x.obj"),
            "x.obj:2: line corner '1//1' is not of the form v or v/vt (line 0)");
  EXPECT_EQ(error_loading("v 0 0 0\np 2\n", "x.obj"), "x.obj:2: point refers to vertex 2, but the file has 1 vertices");
  EXPECT_EQ(error_loading(std::string("\xff\xfe" "v\0", 5), "x.obj"),
            "x.obj: the UTF-16 text has an odd number of bytes (the file is truncated)");
  EXPECT_EQ(error_loading(std::string("\xff\xfe\x00\xd8v\0", 6), "x.obj"),
            "x.obj: the UTF-16 text has an unpaired surrogate at offset 0");
}

TEST(ReaderErrors, Off) {
  EXPECT_EQ(error_loading("4OFF\n3 1 0\n0 0 0 0\n1 0 0 1\n0 1 0 1\n3 0 1 2\n", "x.off"),
            "x.off:3: 4OFF vertex with w = 0 (a point at infinity) (vertex 0)");
  EXPECT_EQ(error_loading("OFF\n353535235358 1 0\n", "x.off"),
            "x.off:2: the OFF vertex count '353535235358' is not a whole number below 2^32");
  EXPECT_EQ(error_loading("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0\n", "x.off"),
            "x.off:6: face has 0 corners; at least 3 are needed (face 0)");
  EXPECT_EQ(error_loading(std::string("OFF BINARY\n\x77\x13\x00\x00\x22\x26\x00\x00\0\0\0\0", 23), "x.off"),
            "x.off: the binary OFF data ends before its 1997733888 vertices (the file is truncated)");
}

}  // namespace
}  // namespace convray::mesh
