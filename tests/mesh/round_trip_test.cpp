// Writing a soup in every format and encoding and reading it back gives the same triangles.
#include <gtest/gtest.h>

#include <bit>
#include <cctype>

#include "mesh/load.hpp"
#include "mesh/procedural.hpp"
#include "mesh/write.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

using testing::on_float_grid;
using testing::ScratchDirectory;

struct Encoding {
  const char* file_name;
  MeshEncoding encoding;
  const char* expected_format;
  bool shares_vertices;  // indexed formats keep the vertex array; STL repeats every corner
};

const Encoding kEncodings[] = {
    {"soup.obj", MeshEncoding::Default, "OBJ", true},
    {"soup.ply", MeshEncoding::Ascii, "PLY ascii", true},
    {"soup.ply", MeshEncoding::Binary, "PLY binary little-endian", true},
    {"soup.stl", MeshEncoding::Ascii, "STL ascii", false},
    {"soup.stl", MeshEncoding::Binary, "STL binary", false},
    {"soup.off", MeshEncoding::Default, "OFF", true},
};

// Same triangles: the same corner positions, triangle by triangle, in the same order.
void expect_same_triangles(const TriangleSoup& expected, const TriangleSoup& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  for (size_t t = 0; t < expected.size(); ++t) {
    ASSERT_EQ(expected.corners(t), actual.corners(t)) << "triangle " << t;
  }
}

class RoundTrip : public ::testing::TestWithParam<Encoding> {};

TEST_P(RoundTrip, GivesTheSameTriangles) {
  ScratchDirectory scratch;
  const Encoding& encoding = GetParam();
  TriangleSoup soup = on_float_grid(icosphere(Vec3(1, 2, 3), 4.0, 2));
  std::string path = scratch.file(encoding.file_name);
  save_mesh(soup, path, encoding.encoding);

  LoadedMesh loaded = load_mesh(path);
  EXPECT_EQ(loaded.format, encoding.expected_format);
  expect_same_triangles(soup, loaded.soup);
  if (encoding.shares_vertices) {
    EXPECT_EQ(loaded.soup.vertices, soup.vertices);
    EXPECT_EQ(loaded.soup.triangles, soup.triangles);
  }
  EXPECT_EQ(loaded.report.faces_read, soup.size());
  EXPECT_EQ(loaded.report.triangles_kept, soup.size());
}

TEST_P(RoundTrip, GivesTheSameTrianglesThroughGzip) {
  ScratchDirectory scratch;
  const Encoding& encoding = GetParam();
  TriangleSoup soup = on_float_grid(torus(3.0, 1.0, 24, 12));
  std::string path = scratch.file(encoding.file_name);
  save_mesh(soup, path, encoding.encoding);
  testing::write_gzip(path + ".gz", testing::read_bytes(path));

  LoadedMesh loaded = load_mesh(path + ".gz");
  EXPECT_EQ(loaded.format, std::string(encoding.expected_format) + ", gzip-compressed");
  expect_same_triangles(soup, loaded.soup);
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, RoundTrip, ::testing::ValuesIn(kEncodings),
                         [](const ::testing::TestParamInfo<Encoding>& info) {
                           std::string name = info.param.expected_format;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

TEST(RoundTrip, ObjKeepsFullDoublePrecision) {
  ScratchDirectory scratch;
  TriangleSoup soup = icosphere(Vec3(0.1, 0.2, 0.3), 1.0 / 3.0, 1);  // nothing here is a float
  save_mesh(soup, scratch.file("precise.obj"));
  EXPECT_EQ(load_mesh(scratch.file("precise.obj")).soup.vertices, soup.vertices);
}

// Each coordinate rounded to float32. Not inlined: GCC 12.2's SLP vectoriser (-O2 and up)
// drops the double -> float -> double round trip of the x and y of such an expression.
[[gnu::noinline]] double rounded_to_float(double x) { return static_cast<float>(x); }
Vec3 rounded_to_float(const Vec3& p) {
  return Vec3(rounded_to_float(p.x), rounded_to_float(p.y), rounded_to_float(p.z));
}

TEST(RoundTrip, PlyDoublesAreExact) {
  // Our writer declares the PLY coordinates double; binary and ASCII alike come back exactly.
  ScratchDirectory scratch;
  TriangleSoup soup = icosphere(Vec3(0.1, 0.2, 0.3), 1.0 / 3.0, 1);  // nothing here is a float
  for (MeshEncoding encoding : {MeshEncoding::Binary, MeshEncoding::Ascii}) {
    save_mesh(soup, scratch.file("precise.ply"), encoding);
    EXPECT_EQ(load_mesh(scratch.file("precise.ply")).soup.vertices, soup.vertices);
  }
}

TEST(RoundTrip, StlRoundsCoordinatesToFloat) {
  // Binary STL stores float32 by definition.
  ScratchDirectory scratch;
  TriangleSoup soup = icosphere(Vec3(0.1, 0.2, 0.3), 1.0 / 3.0, 1);
  save_mesh(soup, scratch.file("precise.stl"), MeshEncoding::Binary);
  LoadedMesh loaded = load_mesh(scratch.file("precise.stl"));
  ASSERT_EQ(loaded.soup.size(), soup.size());
  for (size_t t = 0; t < soup.size(); ++t) {
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(loaded.soup.corners(t)[k], rounded_to_float(soup.corners(t)[k])) << t;
  }
}

TEST(RoundTrip, ExtensionsAreCaseInsensitive) {
  ScratchDirectory scratch;
  TriangleSoup soup = on_float_grid(icosphere(Vec3(0.0), 2.0, 1));
  save_mesh(soup, scratch.file("LOUD.PLY"));
  expect_same_triangles(soup, load_mesh(scratch.file("LOUD.PLY")).soup);
}

TEST(RoundTrip, ReadsBigEndianBinaryPly) {
  // Our writer emits little-endian only; this file is written out by hand.
  std::string header =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  auto big_endian = [](uint32_t bits) {
    return std::string{static_cast<char>(bits >> 24), static_cast<char>(bits >> 16), static_cast<char>(bits >> 8),
                       static_cast<char>(bits)};
  };
  auto float_bits = [&](float value) { return big_endian(std::bit_cast<uint32_t>(value)); };
  std::string body;
  for (float value : {0.0f, 0.0f, 0.0f, 1.5f, 0.0f, 0.0f, 0.0f, 2.25f, -1.0f}) body += float_bits(value);
  body += '\3' + big_endian(0) + big_endian(1) + big_endian(2);

  LoadedMesh loaded = load_mesh_from_memory(header + body, "big.ply");
  EXPECT_EQ(loaded.format, "PLY binary big-endian");
  ASSERT_EQ(loaded.soup.size(), 1u);
  EXPECT_EQ(loaded.soup.vertices[1], Vec3(1.5, 0, 0));
  EXPECT_EQ(loaded.soup.vertices[2], Vec3(0, 2.25, -1));
}

TEST(RoundTrip, WritingLeavesNoTemporaryFilesBehind) {
  ScratchDirectory scratch;
  save_mesh(icosphere(Vec3(0.0), 1.0, 0), scratch.file("a.off"));
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(scratch.file("a.off")).parent_path()))
    ++files;
  EXPECT_EQ(files, 1u);
}

TEST(RoundTrip, RefusesEncodingsAFormatDoesNotHave) {
  ScratchDirectory scratch;
  std::string path = scratch.file("a.obj");
  EXPECT_EQ(testing::input_error_of([&] { save_mesh(icosphere(Vec3(0.0), 1.0, 0), path, MeshEncoding::Binary); }),
            path + ": cannot write obj in binary: the format is text only");
}

}  // namespace
}  // namespace convray::mesh
