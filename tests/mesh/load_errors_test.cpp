// Every malformed input is an InputError that names the file, says what is wrong and, where
// it applies, the element (counted from 0) and the line.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "mesh/load.hpp"
#include "mesh/procedural.hpp"
#include "mesh/write.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

using testing::input_error_of;

std::string error_loading(const std::string& bytes, const std::string& name) {
  return input_error_of([&] { load_mesh_from_memory(bytes, name); });
}

const std::string kPlyAsciiHeader =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 2\nproperty list uchar int vertex_indices\nend_header\n";  // 9 lines

// Bytes of a file written by our writer, for the binary formats.
std::string written(const TriangleSoup& soup, const std::string& name, MeshEncoding encoding) {
  testing::ScratchDirectory scratch;
  save_mesh(soup, scratch.file(name), encoding);
  return testing::read_bytes(scratch.file(name));
}

TriangleSoup two_triangles() {
  TriangleSoup soup;
  soup.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  soup.triangles = {{0, 1, 2}, {1, 3, 2}};
  return soup;
}

// ---- Non-finite coordinates --------------------------------------------------------------

TEST(LoadErrors, NanCoordinateInObj) {
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n", "nan.obj"),
            "nan.obj:2: vertex has a non-finite coordinate 'nan' (vertex 1)");
}

TEST(LoadErrors, InfiniteCoordinateInObj) {
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 0\nv 0 1e999 0\nf 1 2 3\n", "inf.obj"),
            "inf.obj:3: vertex has a non-finite coordinate '1e999' (vertex 2)");
}

TEST(LoadErrors, NanCoordinateInPly) {
  EXPECT_EQ(error_loading(kPlyAsciiHeader + "0 0 0\n1 0 0\n0 nan 0\n1 1 0\n3 0 1 2\n3 1 3 2\n", "nan.ply"),
            "nan.ply:12: vertex has a non-finite coordinate (vertex 2)");
}

TEST(LoadErrors, NanCoordinateInOff) {
  EXPECT_EQ(error_loading("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "nan.off"),
            "nan.off:4: vertex has a non-finite coordinate 'nan' (vertex 1)");
}

TEST(LoadErrors, NanCoordinateInBinaryStl) {
  TriangleSoup soup = two_triangles();
  soup.vertices[3].y = std::nan("");
  EXPECT_EQ(error_loading(written(soup, "nan.stl", MeshEncoding::Binary), "nan.stl"),
            "nan.stl: triangle corner has a non-finite coordinate (face 1)");
}

// ---- Indices out of range ----------------------------------------------------------------

TEST(LoadErrors, IndexOutOfRangeInAsciiPly) {
  EXPECT_EQ(error_loading(kPlyAsciiHeader + "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 90 2\n", "bunny.ply"),
            "bunny.ply:15: face refers to vertex 90, but the file has 4 vertices (face 1)");
}

TEST(LoadErrors, NegativeIndexInBinaryPly) {
  TriangleSoup soup = two_triangles();
  std::string bytes = written(soup, "bad.ply", MeshEncoding::Binary);
  // The last index of the last face is the last four bytes: make it -5 as an int32.
  bytes.replace(bytes.size() - 4, 4, std::string("\xfb\xff\xff\xff", 4));
  // Our writer declares the indices uint: for -5 they must be int.
  bytes.replace(bytes.find("uchar uint"), 10, "uchar int");
  EXPECT_EQ(error_loading(bytes, "bad.ply"), "bad.ply: face refers to vertex -5, but the file has 4 vertices (face 1)");
}

TEST(LoadErrors, IndexOutOfRangeInOff) {
  EXPECT_EQ(error_loading("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 0 1 9\n", "bad.off"),
            "bad.off:8: face refers to vertex 9, but the file has 4 vertices (face 1)");
}

TEST(LoadErrors, IndexOutOfRangeInObj) {
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n", "bad.obj"),
            "bad.obj:5: face refers to vertex 9, but the file has 3 vertices (face 1)");
}

TEST(LoadErrors, RelativeIndexBeforeTheFirstVertexInObj) {
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "bad.obj"),
            "bad.obj:4: face refers to vertex -4, but only 3 vertices precede it (face 0)");
}

TEST(LoadErrors, ZeroIndexInObj) {
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "bad.obj"),
            "bad.obj:4: face corner '0' does not start with a vertex index (a non-zero integer; OBJ counts from 1) "
            "(face 0)");
}

// ---- Truncated files ---------------------------------------------------------------------

TEST(LoadErrors, TruncatedBinaryPly) {
  std::string bytes = written(two_triangles(), "cut.ply", MeshEncoding::Binary);
  EXPECT_EQ(error_loading(bytes.substr(0, bytes.size() - 6), "cut.ply"),
            "cut.ply: the file ends in the middle of the data: the header declares 2 face elements "
            "(the file is truncated) (face 1)");
}

TEST(LoadErrors, TruncatedBinaryPlyInTheVertices) {
  std::string bytes = written(two_triangles(), "cut.ply", MeshEncoding::Binary);
  size_t body = bytes.find("end_header\n") + 11;
  EXPECT_EQ(error_loading(bytes.substr(0, body + 3 * 24 + 5), "cut.ply"),
            "cut.ply: the file ends in the middle of the data: the header declares 4 vertex elements of 24 bytes, "
            "and the data ends after 3 of them (the file is truncated) (vertex 3)");
}

TEST(LoadErrors, PlyHeaderCountBeyondTheData) {
  // A header that promises four billion vertices must not make anyone allocate them.
  std::string bytes = written(two_triangles(), "huge.ply", MeshEncoding::Binary);
  bytes.replace(bytes.find("vertex 4"), 8, "vertex 4000000000");
  EXPECT_EQ(error_loading(bytes, "huge.ply"),
            "huge.ply: the file ends in the middle of the data: the header declares 4000000000 vertex elements of "
            "24 bytes, and the data ends after 5 of them (the file is truncated) (vertex 5)");
}

TEST(LoadErrors, TruncatedAsciiPly) {
  EXPECT_EQ(error_loading(kPlyAsciiHeader + "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n", "cut.ply"),
            "cut.ply: the file ends before all data: the header declares 2 face elements (the file is truncated) "
            "(face 1)");
}

TEST(LoadErrors, AsciiPlyLineWithTooFewValues) {
  EXPECT_EQ(error_loading(kPlyAsciiHeader + "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 0 1\n", "cut.ply"),
            "cut.ply:15: too few values on the line: 'vertex_indices' is missing (the header does not match the data) "
            "(face 1)");
}

TEST(LoadErrors, BinaryStlLongerThanItsCountIsRead) {
  // PyMesh's empty.stl: a count of 0 and one byte more than the 84 of the header.
  EXPECT_EQ(error_loading(std::string(80, ' ') + std::string(4, '\0') + "\n", "empty.stl"),
            "empty.stl: the file has no vertices, so there is nothing to render");
  std::string bytes = written(two_triangles(), "long.stl", MeshEncoding::Binary);
  EXPECT_EQ(load_mesh_from_memory(bytes + "trailing", "long.stl").soup.size(), 2u);
}

TEST(LoadErrors, TruncatedBinaryStl) {
  std::string bytes = written(two_triangles(), "cut.stl", MeshEncoding::Binary);
  EXPECT_EQ(error_loading(bytes.substr(0, bytes.size() - 20), "cut.stl"),
            "cut.stl: binary STL of the wrong size: the header declares 2 triangles, which take 84 + 50 x 2 = 184 "
            "bytes, but the file has 164 bytes (the file is truncated)");
}

TEST(LoadErrors, TruncatedAsciiStl) {
  std::string bytes = written(two_triangles(), "cut.stl", MeshEncoding::Ascii);
  // Between facets the end of the file ends the solid (OpenMesh leaves `endsolid` out).
  EXPECT_EQ(load_mesh_from_memory(bytes.substr(0, bytes.find("endsolid")), "cut.stl").soup.size(), 2u);
  EXPECT_EQ(error_loading(bytes.substr(0, bytes.rfind("endloop")), "cut.stl"),
            "cut.stl: ASCII STL: the file ends before 'endsolid' (the file is truncated) (face 1)");
  size_t last_vertex = bytes.rfind("vertex");  // on line 13, in face 1
  EXPECT_EQ(error_loading(bytes.substr(0, last_vertex + 9), "cut.stl"),
            "cut.stl:13: ASCII STL: expected three numbers on the line (face 1)");
}

TEST(LoadErrors, ObjVertexWithMissingCoordinate) {
  // Two coordinates are a 2D vertex (z = 0); one is too few.
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 0\nv 0", "cut.obj"),
            "cut.obj:3: vertex has 1 coordinate; at least 2 are needed (vertex 2)");
}

TEST(LoadErrors, ObjFaceWithMissingCorner) {
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2", "cut.obj"),
            "cut.obj:5: face has 2 corners; at least 3 are needed (face 1)");
}

TEST(LoadErrors, ObjCoordinateThatIsNotANumber) {
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0,5 0\nv 0 1 0\nf 1 2 3\n", "bad.obj"),
            "bad.obj:2: vertex coordinate '0,5' is not a number (vertex 1)");
}

TEST(LoadErrors, TruncatedOffFaces) {
  EXPECT_EQ(error_loading("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n", "cut.off"),
            "cut.off: the file ends after 1 of the 2 faces the header declares (the file is truncated) (face 1)");
}

TEST(LoadErrors, TruncatedOffVertices) {
  EXPECT_EQ(error_loading("OFF\n4 2 0\n0 0 0\n1 0 0\n", "cut.off"),
            "cut.off: the file ends after 2 of the 4 vertices the header declares (the file is truncated) "
            "(vertex 2)");
}

TEST(LoadErrors, OffFaceWithMissingIndex) {
  EXPECT_EQ(error_loading("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 0 1\n", "cut.off"),
            "cut.off: the file ends in the middle of face 1: 2 of its 3 corners are there (the file is truncated) "
            "(face 1)");
}

TEST(LoadErrors, OffVertexWithMissingCoordinate) {
  // OFF is whitespace-separated: vertex 1 takes its z from the next line (whose rest is
  // skipped as colours would be), vertex 2 takes the face's line, and the face is missing.
  EXPECT_EQ(error_loading("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "cut.off"),
            "cut.off: the file ends after 0 of the 1 faces the header declares (the file is truncated) (face 0)");
}

// ---- Not a mesh at all ----------------------------------------------------------------

TEST(LoadErrors, UnknownFormat) {
  EXPECT_EQ(error_loading("v 0 0 0\n", "points.xyz"),
            "points.xyz: unknown mesh format '.xyz' (expected .obj, .ply, .stl, .off, optionally .gz)");
  EXPECT_EQ(error_loading("", "archive.tar.gz"),
            "archive.tar.gz: unknown mesh format '.tar.gz' (expected .obj, .ply, .stl, .off, optionally .gz)");
  EXPECT_EQ(error_loading("", "README"),
            "README: unknown mesh format: the name has no extension (expected .obj, .ply, .stl, .off, optionally .gz)");
}

// is_mesh_file_name says yes exactly where load_mesh picks a reader rather than refusing
// the name as an unknown format.
TEST(LoadErrors, IsMeshFileNameAgreesWithTheFormatLoadMeshPicks) {
  for (const char* name : {"a.obj", "B.PLY", "c.stl", "d.Off", "bunny.ply.gz", "x/y.OBJ.GZ"}) {
    EXPECT_TRUE(is_mesh_file_name(name)) << name;
    EXPECT_EQ(input_error_of([&] { load_mesh(std::string("/nonexistent/") + name); })
                  .find("unknown mesh format"),
              std::string::npos)
        << name;
  }
  for (const char* name : {"scene.pov", "points.xyz", "archive.tar.gz", "README", "dir.obj/file",
                           ".gz", "model.gz"}) {
    EXPECT_FALSE(is_mesh_file_name(name)) << name;
    EXPECT_NE(input_error_of([&] { load_mesh(std::string("/nonexistent/") + name); })
                  .find("unknown mesh format"),
              std::string::npos)
        << name;
  }
}

TEST(LoadErrors, UnknownFormatIsReportedBeforeOpeningTheFile) {
  EXPECT_EQ(input_error_of([] { load_mesh("/nonexistent/model.3ds"); }),
            "/nonexistent/model.3ds: unknown mesh format '.3ds' (expected .obj, .ply, .stl, .off, optionally .gz)");
}

TEST(LoadErrors, MissingFile) {
  EXPECT_EQ(input_error_of([] { load_mesh("/nonexistent/model.ply"); }),
            "/nonexistent/model.ply: cannot open the file: No such file or directory");
}

TEST(LoadErrors, Directory) {
  testing::ScratchDirectory scratch;
  std::filesystem::create_directory(scratch.file("folder.ply"));
  EXPECT_EQ(input_error_of([&] { load_mesh(scratch.file("folder.ply")); }),
            scratch.file("folder.ply") + ": cannot read the file: it is a folder, not a file");
}

// A named pipe would wait for a writer, /dev/zero would never end, a loop of links has no file
// at its end: each named for what it is before anything is opened.
TEST(LoadErrors, PipesDevicesAndLinkLoops) {
  testing::ScratchDirectory scratch;
  ASSERT_EQ(::mkfifo(scratch.file("pipe.ply").c_str(), 0600), 0);
  std::filesystem::create_symlink("/dev/zero", scratch.file("zero.ply"));
  std::filesystem::create_symlink(scratch.file("b.ply"), scratch.file("a.ply"));
  std::filesystem::create_symlink(scratch.file("a.ply"), scratch.file("b.ply"));
  EXPECT_EQ(input_error_of([&] { load_mesh(scratch.file("pipe.ply")); }),
            scratch.file("pipe.ply") + ": cannot read the file: it is a named pipe, not a file");
  EXPECT_EQ(
      input_error_of([&] { load_mesh(scratch.file("zero.ply")); }),
      scratch.file("zero.ply") + ": cannot read the file: it is a character device, not a file");
  EXPECT_EQ(input_error_of([&] { load_mesh(scratch.file("a.ply")); }),
            scratch.file("a.ply") + ": cannot read the file: it is a loop of symbolic links");
}

TEST(LoadErrors, EmptyFile) {
  for (const char* name : {"empty.obj", "empty.ply", "empty.stl", "empty.off", "empty.ply.gz"}) {
    EXPECT_EQ(error_loading("", name), std::string(name) + ": the file is empty");
  }
}

// A face is counted once however many triangles it has: one 255-corner face (the most a PLY
// list with a uchar count holds) naming one vertex 255 times, or with its corners on a line.
TEST(LoadErrors, ADroppedPolygonIsOneFace) {
  std::string header =
      "ply\nformat ascii 1.0\nelement vertex 255\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  std::string vertices, repeated = "255", line = "255";
  for (int i = 0; i < 255; ++i) {
    vertices += std::to_string(i) + " 0 0\n";
    repeated += " 0";
    line += " " + std::to_string(i);
  }
  EXPECT_EQ(error_loading(header + vertices + repeated + "\n", "repeated.ply"),
            "repeated.ply: nothing left to render: all 1 faces are degenerate (0 with zero area, 1 "
            "with a repeated vertex)");
  EXPECT_EQ(error_loading(header + vertices + line + "\n", "line.ply"),
            "line.ply: nothing left to render: all 1 faces are degenerate (1 with zero area, 0 "
            "with a repeated vertex)");
}

TEST(LoadErrors, NothingToRender) {
  // Vertices alone are a point cloud; a file with no vertex at all has nothing.
  EXPECT_EQ(error_loading("# nothing but a comment\n", "none.obj"),
            "none.obj: the file has no vertices, so there is nothing to render");
  EXPECT_EQ(error_loading("OFF\n0 0 0\n", "none.off"), "none.off: the file has no vertices, so there is nothing to render");
  EXPECT_EQ(error_loading("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n", "flat.obj"),
            "flat.obj: nothing left to render: all 2 faces are degenerate (1 with zero area, 1 with a repeated "
            "vertex)");
  EXPECT_EQ(error_loading("v 0 0 0\nv 0 0 0\nl 1 2 1\n", "dot.obj"),
            "dot.obj: nothing left to render: all 2 segments of the 1 lines have zero length");
}

const std::string kGarbage("\x8f\x01garbage\x00\xff\x13\x37 not a mesh \x7f\x02", 26);

TEST(LoadErrors, GarbageBytes) {
  EXPECT_EQ(error_loading(kGarbage, "junk.ply"), "junk.ply: not a PLY file: it does not start with the line 'ply'");
  EXPECT_EQ(error_loading(kGarbage, "junk.obj"),
            "junk.obj: the file contains the control byte 0x01 at offset 1, which has no place in an OBJ (text) file");
  EXPECT_EQ(error_loading(kGarbage, "junk.off"),
            "junk.off:1: not an OFF file: it does not start with the keyword OFF (or COFF, NOFF, STOFF, 4OFF, ...)");
  EXPECT_EQ(error_loading("OFF\n3 1 0\n0 0 0\x01\n", "ctl.off"),
            "ctl.off: the file contains a control byte at offset 15, which has no place in an OFF text file (binary "
            "OFF starts with 'OFF BINARY')");
  EXPECT_EQ(error_loading(kGarbage, "junk.stl"),
            "junk.stl: not an STL file: too short for a binary STL (26 bytes, the header alone is 84) and not "
            "ASCII STL (it does not start with 'solid')");
}

TEST(LoadErrors, TextThatIsNoMesh) {
  EXPECT_EQ(error_loading("Dear reader,\nthis is a letter.\n", "letter.off"),
            "letter.off:1: not an OFF file: it does not start with the keyword OFF (or COFF, NOFF, STOFF, 4OFF, ...)");
}

// ---- gzip ------------------------------------------------------------------------------

std::string gzipped(const std::string& bytes) {
  testing::ScratchDirectory scratch;
  testing::write_gzip(scratch.file("x.gz"), bytes);
  return testing::read_bytes(scratch.file("x.gz"));
}

TEST(LoadErrors, CorruptedGzip) {
  std::string text = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::string bytes = gzipped(text);
  bytes[bytes.size() - 6] ^= 0x55;  // inside the CRC-32 of the trailer
  EXPECT_EQ(error_loading(bytes, "tri.off.gz"), "tri.off.gz: gzip: corrupt data (incorrect data check)");
}

// The trailer's length (ISIZE) is checked as its CRC is, whether it states more or less than
// the data holds (the reader also sizes its buffer from it).
TEST(LoadErrors, GzipWhoseTrailerStatesAnotherLength) {
  const std::string text = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  for (const unsigned char stated : {uint8_t(text.size() - 1), uint8_t(text.size() + 1), uint8_t(200)}) {
    std::string bytes = gzipped(text);
    bytes[bytes.size() - 4] = char(stated);
    EXPECT_EQ(error_loading(bytes, "tri.off.gz"), "tri.off.gz: gzip: corrupt data (incorrect length check)")
        << int(stated);
  }
}

TEST(LoadErrors, TruncatedGzip) {
  std::string bytes = gzipped("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(error_loading(bytes.substr(0, bytes.size() - 10), "tri.off.gz"),
            "tri.off.gz: gzip: the compressed data ends early (the file is truncated)");
}

TEST(LoadErrors, NotGzipAtAll) {
  EXPECT_EQ(error_loading("OFF\n3 1 0\n", "tri.off.gz"),
            "tri.off.gz: gzip: not gzip data (the file does not start with 1f 8b)");
}

TEST(LoadErrors, DecompressionBomb) {
  std::string bytes = gzipped(std::string(4 << 20, '\0'));  // 4 MiB of zeros: about 4 KiB compressed
  EXPECT_EQ(error_loading(bytes, "bomb.ply.gz"),
            "bomb.ply.gz: gzip: the decompressed data exceeds 1048576 bytes (100 times the compressed size, at least "
            "1 MiB, at most 4 GiB); refusing what looks like a decompression bomb");
}

TEST(LoadErrors, ErrorsInsideGzipNameTheGzipFile) {
  std::string bytes = gzipped("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 0 1 9\n");
  EXPECT_EQ(error_loading(bytes, "bad.off.gz"),
            "bad.off.gz:8: face refers to vertex 9, but the file has 4 vertices (face 1)");
}

TEST(LoadErrors, AreInputErrorsWithTheFileAsLocation) {
  try {
    load_mesh_from_memory("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "loc.off");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.loc().file, "loc.off");
    EXPECT_EQ(error.loc().line, 6);
    EXPECT_EQ(error.message(), "face refers to vertex 7, but the file has 3 vertices (face 0)");
  }
}

}  // namespace
}  // namespace convray::mesh
