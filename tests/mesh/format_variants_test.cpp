// The many ways the formats can legitimately be written, and the few we refuse on purpose.
#include <gtest/gtest.h>

#include "mesh/load.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

using testing::input_error_of;

size_t triangles_in(const std::string& bytes, const std::string& name) {
  return load_mesh_from_memory(bytes, name).soup.size();
}

TEST(FormatVariants, OffWithCommentsColoursAndCountsOnTheKeywordLine) {
  EXPECT_EQ(triangles_in("# made by hand\nOFF 4 2 0 # counts\n\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n", "a.off"), 2u);
  EXPECT_EQ(triangles_in("COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2 255 0 0\n", "c.off"), 1u);
  EXPECT_EQ(triangles_in("OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n", "crlf.off"), 1u);
}

TEST(FormatVariants, OffFacesOfMoreThanNineCorners) {
  // assimp's OFF reader dropped them silently. Ten corners on the convex parabola y = x^2
  // are 10 - 2 = 8 triangles.
  std::string off = "OFF\n10 1 0\n";
  for (int k = 0; k < 10; ++k) off += std::to_string(k) + " " + std::to_string(k * k) + " 0\n";
  off += "10 0 1 2 3 4 5 6 7 8 9\n";
  EXPECT_EQ(triangles_in(off, "big.off"), 8u);
}

TEST(FormatVariants, PlyWithMoreElementsAndProperties) {
  std::string ply =
      "ply\r\nformat ascii 1.0\r\ncomment scanned\r\nobj_info x\r\nelement vertex 3\r\nproperty double x\r\n"
      "property double y\r\nproperty double z\r\nproperty float confidence\r\nproperty uchar red\r\n"
      "element face 1\r\nproperty list uint int vertex_index\r\nproperty int flags\r\nelement edge 1\r\n"
      "property int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
      "0 0 0 0.5 255\r\n1 0 0 0.5 0\r\n0 1 0 1 7\r\n3 0 1 2 0\r\n0 1\r\n";
  LoadedMesh mesh = load_mesh_from_memory(ply, "rich.ply");
  EXPECT_EQ(mesh.soup.size(), 1u);
  EXPECT_EQ(mesh.soup.vertices[1], Vec3(1, 0, 0));
}

TEST(FormatVariants, PlyRefusals) {
  const std::string start = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n";
  EXPECT_EQ(input_error_of([&] { load_mesh_from_memory(start + "end_header\n", "a.ply"); }),
            "a.ply: the PLY vertex element has no scalar property 'z'");
  EXPECT_EQ(input_error_of([&] {
              load_mesh_from_memory(start + "property float z\nelement tristrips 1\nproperty int vertex_indices\n"
                                            "end_header\n", "b.ply");
            }),
            "b.ply: the PLY tristrips element has no list of integer 'vertex_indices'");
  EXPECT_EQ(input_error_of([&] { load_mesh_from_memory(start + "property int128 z\n", "c.ply"); }),
            "c.ply:6: unknown PLY type 'int128'");
  EXPECT_EQ(input_error_of([&] {
              load_mesh_from_memory("ply\nelement vertex 0\nproperty float x\nend_header\n", "f.ply");
            }),
            "f.ply:4: the PLY header has no format line ('format ascii 1.0' or binary)");
}

TEST(FormatVariants, PlyDataBeyondWhatTheHeaderDeclaresIsIgnored) {
  // Values after the declared ones on a line, lines after the last element (VCG writes both).
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 7 7\n1 0 0\n0 1 0\n3 0 1 2 9 9\n"
      "0 0 1\n";
  const LoadedMesh mesh = load_mesh_from_memory(ply, "extra.ply");
  EXPECT_EQ(mesh.soup.vertices.size(), 3u);
  EXPECT_EQ(mesh.soup.size(), 1u);
}

TEST(FormatVariants, PlyBlankLinesInTheDataCarryNoValues) {
  EXPECT_EQ(triangles_in("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n0 1 0\n\n3 0 1 2\n\n",
                         "d.ply"),
            1u);
}

TEST(FormatVariants, GzipWithSeveralMembers) {
  // `cat a.gz b.gz` is a valid gzip file of the two contents one after the other.
  testing::ScratchDirectory scratch;
  testing::write_gzip(scratch.file("a.gz"), "v 0 0 0\nv 1 0 0\n");
  testing::write_gzip(scratch.file("b.gz"), "v 0 1 0\nf 1 2 3\n");
  std::string both = testing::read_bytes(scratch.file("a.gz")) + testing::read_bytes(scratch.file("b.gz"));
  EXPECT_EQ(triangles_in(both, "joined.obj.gz"), 1u);
}

// The reader sizes its buffer from the size in the last four bytes (the trailer's ISIZE) when
// that is right; bytes after the last member (ignored, as gzip(1) ignores them) make it say
// anything: smaller, larger, zero. The content read is the same.
TEST(FormatVariants, GzipTrailingBytesWhateverSizeTheyState) {
  testing::ScratchDirectory scratch;
  testing::write_gzip(scratch.file("a.gz"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const std::string member = testing::read_bytes(scratch.file("a.gz"));
  for (const std::string& tail : {std::string("\x01\0\0\0", 4), std::string("\xff\xff\0\0", 4),
                                  std::string("\0\0\0\0", 4), std::string("\xff\xff\xff\xff", 4)}) {
    EXPECT_EQ(triangles_in(member + tail, "tail.off.gz"), 1u);
  }
}

TEST(FormatVariants, UppercaseGzipExtension) {
  testing::ScratchDirectory scratch;
  testing::write_gzip(scratch.file("a.gz"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(load_mesh_from_memory(testing::read_bytes(scratch.file("a.gz")), "TRI.OFF.GZ").format,
            "OFF, gzip-compressed");
}

TEST(FormatVariants, StlKeywordsInCapitals) {
  // Some CAD exporters write the ASCII keywords in capitals.
  EXPECT_EQ(triangles_in("SOLID part\nFACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\nVERTEX 0 1 0\n"
                         "ENDLOOP\nENDFACET\nENDSOLID part\n", "caps.stl"),
            1u);
}

TEST(FormatVariants, PlyIntegersWrittenAsReals) {
  // "3.0 0.0 1.0 2.0": whole numbers with a decimal point are the integers they name.
  EXPECT_EQ(triangles_in("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n0 1 0\n3.0 0.0 1.0 2e0\n", "reals.ply"),
            1u);
  EXPECT_EQ(testing::input_error_of([] {
              load_mesh_from_memory("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                    "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", "half.ply");
            }),
            "half.ply:13: value '1.5' of 'vertex_indices' is not an int (face 0)");
}

}  // namespace
}  // namespace convray::mesh
