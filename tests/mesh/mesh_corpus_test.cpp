// The corpus of tests/data/meshes/: one small file per variant of the formats users have
// (issue 23), written by tests/data/meshes/make_meshes.py. The counts below are worked out by
// hand from what that script writes (tests/data/meshes/README.md says how for each file), not
// taken from what convray reads.
#include <gtest/gtest.h>

#include <string>

#include "mesh/load.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

std::string corpus_file(const std::string& name) { return std::string(CONVRAY_SOURCE_DIR) + "/tests/data/meshes/" + name; }

struct Expected {
  const char* file;
  size_t triangles, segments, points;
};

// A cube of 6 quads is 12 triangles; a convex polygon of n corners is n - 2.
const Expected kReadable[] = {
    // PLY
    {"ply_ascii_cube.ply", 12, 0, 0},
    {"ply_ascii_crlf.ply", 12, 0, 0},
    {"ply_face_before_vertex.ply", 12, 0, 0},
    {"ply_header_extra_lines.ply", 6, 0, 0},          // 3 quads
    {"ply_tristrips.ply", 6, 0, 0},                   // strips of 4 and 2; a stitching strip of none
    {"ply_tristrips_binary.ply", 6, 0, 0},
    {"ply_camera_first.ply", 12, 0, 0},
    {"ply_binary_starts_with_newline.ply", 1, 0, 0},
    {"ply_all_types_be.ply", 12, 0, 0},
    {"ply_all_types_le.ply", 12, 0, 0},
    {"ply_all_types_ascii.ply", 12, 0, 0},
    {"ply_points.ply", 0, 0, 5},
    {"ply_points_empty_face.ply", 0, 0, 4},
    {"ply_edges.ply", 0, 12, 0},                      // the cube's 12 edges
    {"ply_faces_and_edges.ply", 2, 4, 0},             // the bottom quad, the 4 vertical edges
    // OBJ
    {"obj_continuation.obj", 12, 0, 0},
    {"obj_polygon_300.obj", 298, 0, 0},
    {"obj_corner_forms.obj", 13, 0, 0},               // 6 quads and a triangle
    {"obj_2d.obj", 2, 0, 0},
    {"obj_4d.obj", 1, 0, 0},
    {"obj_negative_and_forward.obj", 2, 0, 0},
    {"obj_utf16le.obj", 12, 0, 0},
    {"obj_utf16be.obj", 12, 0, 0},
    {"obj_utf8_bom.obj", 12, 0, 0},
    {"obj_points.obj", 0, 0, 6},
    {"obj_p.obj", 0, 0, 3},
    {"obj_lines.obj", 0, 4, 0},                       // polylines of 4 and 2 corners: 3 + 1
    {"obj_mixed.obj", 12, 2, 1},
    // STL
    {"stl_ascii_solids.stl", 12, 0, 0},               // solids of 4, 0 and 8 facets
    {"stl_binary_solid_header.stl", 12, 0, 0},
    // OFF
    {"off_face_across_lines.off", 12, 0, 0},
    {"off_counts_glued.off", 12, 0, 0},
    {"off_noff3.off", 12, 0, 0},
    {"off_homogeneous.off", 1, 0, 0},
    {"off_colours_comments.off", 12, 0, 0},
    {"off_polygon_12.off", 10, 0, 0},
    {"off_points.off", 0, 0, 4},
    {"off_binary.off", 12, 0, 0},
    {"off_binary_little_endian.off", 12, 0, 0},
};

class CorpusCounts : public ::testing::TestWithParam<Expected> {};

TEST_P(CorpusCounts, TrianglesSegmentsAndPoints) {
  const Expected& e = GetParam();
  const LoadedMesh mesh = load_mesh(corpus_file(e.file));
  EXPECT_EQ(mesh.soup.size(), e.triangles);
  EXPECT_EQ(mesh.segments.size(), e.segments);
  EXPECT_EQ(mesh.points.size(), e.points);
}

std::string test_name(const ::testing::TestParamInfo<Expected>& info) {
  std::string name = info.param.file;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusCounts, ::testing::ValuesIn(kReadable), test_name);

struct Refused {
  const char* file;
  const char* message;  // after "PATH"
};

const Refused kRefused[] = {
    {"broken_ply_header_mismatch.ply",
     ":13: too few values on the line: 'nx' is missing (the header does not match the data) (vertex 0)"},
    {"broken_ply_truncated.ply",
     ": the file ends in the middle of the data: the header declares 6 face elements (the file is truncated) "
     "(face 5)"},
    {"broken_ply_index.ply", ":13: face refers to vertex 8, but the file has 3 vertices (face 0)"},
    {"broken_ply_no_end_header.ply", ": the PLY header has no end_header line (the file may be truncated)"},
    {"broken_obj_two_corners.obj", ":4: face has 2 corners; at least 3 are needed (face 0)"},
    {"broken_obj_index.obj", ":4: face refers to vertex 4, but the file has 3 vertices (face 0)"},
    {"broken_obj_vertex.obj", ":2: vertex has 1 coordinate; at least 2 are needed (vertex 1)"},
    {"broken_stl_truncated.stl",
     ": binary STL of the wrong size: the header declares 12 triangles, which take 84 + 50 x 12 = 684 bytes, but "
     "the file has 659 bytes (the file is truncated)"},
    {"broken_off_dimension.off", ":2: nOFF of dimension 4: only 3-dimensional vertices are supported"},
    {"broken_off_index.off", ":6: face refers to vertex 3, but the file has 3 vertices (face 0)"},
};

class CorpusRefusals : public ::testing::TestWithParam<Refused> {};

TEST_P(CorpusRefusals, Message) {
  const Refused& r = GetParam();
  const std::string path = corpus_file(r.file);
  EXPECT_EQ(testing::input_error_of([&] { load_mesh(path); }), path + r.message);
}

std::string refused_name(const ::testing::TestParamInfo<Refused>& info) {
  return test_name({{info.param.file, 0, 0, 0}, info.index});
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusRefusals, ::testing::ValuesIn(kRefused), refused_name);

// ---- Coordinates where the variant decides them ------------------------------------------

TEST(CorpusValues, ObjFourthCoordinateIsIgnored) {
  // w is a weight for rational curves and surfaces, not a homogeneous divisor.
  const LoadedMesh mesh = load_mesh(corpus_file("obj_4d.obj"));
  EXPECT_EQ(mesh.soup.vertices[1], Vec3(2, 0, 0));
  EXPECT_EQ(mesh.soup.vertices[2], Vec3(0, 2, 0));
}

TEST(CorpusValues, ObjTwoCoordinatesMeanZeroZ) {
  const LoadedMesh mesh = load_mesh(corpus_file("obj_2d.obj"));
  EXPECT_EQ(mesh.soup.vertices[2], Vec3(1, 1, 0));
}

TEST(CorpusValues, OffFourthCoordinateDivides) {
  const LoadedMesh mesh = load_mesh(corpus_file("off_homogeneous.off"));
  EXPECT_EQ(mesh.soup.vertices[1], Vec3(1, 0, 0));
  EXPECT_EQ(mesh.soup.vertices[2], Vec3(0, 1, 0));
}

TEST(CorpusValues, PlyBinaryBodyStartingWithALineFeed) {
  // x of vertex 0 has the float32 bits 0x3f80000a: 1 + 10 x 2^-23.
  const LoadedMesh mesh = load_mesh(corpus_file("ply_binary_starts_with_newline.ply"));
  EXPECT_EQ(mesh.soup.vertices[0].x, 1.0 + 10.0 / 8388608.0);
}

TEST(CorpusValues, PlyCoordinatesOfEveryType) {
  // x is an int16, y a float64, z a uint8: the cube's corners, in all three encodings.
  for (const char* name : {"ply_all_types_be.ply", "ply_all_types_le.ply", "ply_all_types_ascii.ply"}) {
    const LoadedMesh mesh = load_mesh(corpus_file(name));
    ASSERT_EQ(mesh.soup.vertices.size(), 8u) << name;
    EXPECT_EQ(mesh.soup.vertices[6], Vec3(1, 1, 1)) << name;
    EXPECT_EQ(mesh.soup.vertices[3], Vec3(0, 1, 0)) << name;
  }
}

TEST(CorpusValues, PlyTriangleStripsFaceOneWay) {
  // The grid lies in z = 0; the strip's first triangle (4 0 5), from (0,1) to (0,0) to (1,1),
  // turns counter-clockwise seen from +z, and every other triangle is reversed so that all
  // six turn the same way.
  const LoadedMesh mesh = load_mesh(corpus_file("ply_tristrips.ply"));
  for (size_t t = 0; t < mesh.soup.size(); ++t) {
    const auto c = mesh.soup.corners(t);
    EXPECT_GT(glm::cross(c[1] - c[0], c[2] - c[0]).z, 0.0) << "triangle " << t;
  }
}

TEST(CorpusValues, PointsAndSegmentsOfAMixedObj) {
  const LoadedMesh mesh = load_mesh(corpus_file("obj_mixed.obj"));
  ASSERT_EQ(mesh.points.size(), 1u);
  EXPECT_EQ(mesh.soup.vertices[mesh.points[0]], Vec3(5, 5, 5));
  ASSERT_EQ(mesh.segments.size(), 2u);
  EXPECT_EQ(mesh.soup.vertices[mesh.segments[0][1]], Vec3(1, 1, 1));  // `l 1 7 2`: vertex 7
}

}  // namespace
}  // namespace convray::mesh
