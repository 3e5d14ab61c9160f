// The ASCII PLY body's two ways through a face line: the shortcut for a plainly written list
// (AsciiPlyBody::read_plain_list) and the general tokenizer. A line that starts with a blank
// always goes the general way, and a leading blank changes nothing else about a line, so a
// file and the same file with a blank before every body line must read the same (or fail
// with the same message). Files built from known faces must also read as those faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "mesh/polygon_mesh.hpp"
#include "mesh/readers.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

std::string header(int vertices, int faces, const std::string& list_types = "uchar int") {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
         "\nproperty list " + list_types + " vertex_indices\nend_header\n";
}

// Every line after end_header with a blank in front.
std::string general_way(const std::string& ply) {
  const size_t body = ply.find("end_header\n") + 11;
  std::string out = ply.substr(0, body);
  bool line_start = true;
  for (size_t k = body; k < ply.size(); ++k) {
    if (line_start) out += ' ';
    out += ply[k];
    line_start = ply[k] == '\n';
  }
  return out;
}

// What reading gives: the faces and vertices, or the error.
struct Outcome {
  std::vector<int64_t> items;
  std::vector<size_t> ends;
  std::vector<Vec3> vertices;
  std::string error;
  bool operator==(const Outcome&) const = default;
};

Outcome outcome_of(const std::string& ply) {
  Outcome outcome;
  try {
    PolygonMesh mesh = read_ply(ply, "t.ply");
    outcome.items = mesh.faces.items, outcome.ends = mesh.faces.ends, outcome.vertices = mesh.vertices;
  } catch (const InputError& error) {
    outcome.error = error.what();
  }
  return outcome;
}

void expect_both_ways_alike(const std::string& ply) {
  const Outcome plain = outcome_of(ply), general = outcome_of(general_way(ply));
  EXPECT_EQ(plain.error, general.error) << ply;
  EXPECT_TRUE(plain == general) << ply;
}

std::string vertex_lines(int count) {
  std::string lines;
  for (int v = 0; v < count; ++v) lines += std::to_string(v) + " " + std::to_string(v * v % 7) + " 0.5\n";
  return lines;
}

TEST(PlyTextLines, KnownFacesWrittenInManyWays) {
  std::mt19937 random(7);
  const char* separators[] = {" ", "  ", "\t", " \t "};
  const int vertices = 1000, faces = 3000;
  std::vector<int64_t> items;
  std::vector<size_t> ends;
  std::string body;
  for (int f = 0; f < faces; ++f) {
    const int corners = 3 + static_cast<int>(random() % 4);
    const std::string separator = separators[random() % 4];
    if (random() % 20 == 0) body += random() % 2 ? "\n" : "  \t\n";  // blank lines are skipped
    body += (random() % 10 == 0 ? "00" : "") + std::to_string(corners);
    for (int k = 0; k < corners; ++k) {
      const int64_t index = static_cast<int64_t>(random() % vertices);
      items.push_back(index);
      body += separator + std::to_string(index);
    }
    ends.push_back(items.size());
    if (random() % 5 == 0) body += " 0.25 7";                                   // ignored values
    if (random() % 3 == 0) body += separator;                                   // trailing blanks
    body += random() % 4 == 0 ? "\r\n" : "\n";
  }
  const std::string ply = header(vertices, faces) + vertex_lines(vertices) + body;
  const Outcome read = outcome_of(ply);
  ASSERT_EQ(read.error, "");
  EXPECT_EQ(read.items, items);
  EXPECT_EQ(read.ends, ends);
  EXPECT_EQ(read.vertices.size(), size_t{vertices});
  expect_both_ways_alike(ply);
  expect_both_ways_alike(ply.substr(0, ply.size() - 1));  // no line end after the last face
}

TEST(PlyTextLines, OddAndWrongFaceLinesReadAsTheGeneralWayReadsThem) {
  const std::string odd[] = {
      "3 0 1 2", "3 0 1 2 ", "3\t0\t1\t2", "003 000 01 2", "+3 0 1 2", "3 +0 1 2", "3 0 1 -2", "-3 0 1 2",
      "3 0 1 2.0", "3.0 0 1 2", "3 0 1 1e0", "3 0 1 0x2", "3 0 1 nan", "3 0 1 inf", "3 0 1", "3 0 1 2x",
      "3 0 1 2 x", "2 0 1", "0", "1 0", "256 0 1 2", "255 0 1 2", "3 0 1 9", "3 0 1 4294967296",
      "3 0 1 2147483648", "3 0 1 99999999999999999999", "3 0 1 999999999999999999", "3 0 1 2\r",
      "3 0 1\r2", "3 0 1 2\r5", "3 0 1 2 \x01", "3 0\x01 1 2", "3 0 1 2\x00", "3 0 1 2\t\r", "x 0 1 2",
      "3 0 1 2 # comment", "# comment", "", "3 0 1 2\n", "3 0 1 2 3 0 1 2", "3,0,1,2", "3 0,1 2",
  };
  for (const std::string& line : odd) {
    for (const char* types : {"uchar int", "int int", "uchar uchar", "ushort uint", "char short"}) {
      const std::string ply = header(4, 2, types) + vertex_lines(4) + "3 1 2 3\n" + line + "\n";
      SCOPED_TRACE(line + " / " + types);
      expect_both_ways_alike(ply);
      expect_both_ways_alike(ply.substr(0, ply.size() - 1));
    }
  }
}

TEST(PlyTextLines, RandomMutationsReadAsTheGeneralWayReadsThem) {
  std::mt19937 random(11);
  const std::string pieces[] = {"0", "1", "2", "3", "4", "17", "-1", "+2", " ", "  ", "\t", "\r", "\n", "\r\n",
                                "3.5", "1e1", "255", "256", "65536", "4294967295", "99999999999999999999", "x",
                                "#", "\x01", std::string(1, '\0'), "nan"};
  for (int trial = 0; trial < 3000; ++trial) {
    std::string body;
    const int length = static_cast<int>(random() % 16);
    for (int k = 0; k < length; ++k) body += pieces[random() % std::size(pieces)];
    std::string ply = header(5, 2, random() % 2 ? "uchar int" : "int uint") + vertex_lines(5) + "3 0 1 2\n";
    ply += (random() % 2 ? "4 1 2 3 4 " : "") + body;
    expect_both_ways_alike(ply);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(PlyTextLines, ControlBytesAndLoneReturnsAreFoundOnTheirLine) {
  // Past the first 64-byte block, before it, and on the last line without a line end.
  std::string lines = vertex_lines(40);
  std::string faces = "3 0 1 2\n3 1 2 3\n";
  std::string ply = header(40, 2) + lines + faces;
  const int first_body_line = 10, last_line = first_body_line + 41;
  EXPECT_EQ(outcome_of(ply).error, "");
  std::string with_control = ply;
  with_control.insert(with_control.rfind("3 1 2 3") + 4, "\x02");
  EXPECT_EQ(outcome_of(with_control).error,
            "t.ply:" + std::to_string(last_line) + ": the ASCII PLY data contains the control byte '\\x02'");
  std::string with_return = ply;
  with_return.insert(with_return.find("\n", with_return.find("end_header\n") + 11 + 200), "\r\r");
  const int line_of_return =
      first_body_line + static_cast<int>(std::count(with_return.begin() + static_cast<long>(ply.find("end_header\n") + 11),
                                                     with_return.begin() + static_cast<long>(with_return.find('\r')), '\n'));
  EXPECT_EQ(outcome_of(with_return).error,
            "t.ply:" + std::to_string(line_of_return) + ": a line ends in a lone carriage return; PLY lines end in LF or CR LF");
  // A CR that is the body's last byte ends its last line, as before.
  EXPECT_EQ(outcome_of(ply.substr(0, ply.size() - 1) + "\r").error, "");
  expect_both_ways_alike(with_control);
  expect_both_ways_alike(with_return);
}

TEST(PlyTextLines, AHeaderThatClaimsBillionsOfFacesReservesNoMoreThanTheFileHolds) {
  // Reserving room for 4e9 faces would need 32 GB for their ends alone: a bad_alloc, not this.
  const std::string ply = header(3, 0).replace(header(3, 0).find("face 0"), 6, "face 4000000000") +
                          vertex_lines(3) + "3 0 1 2\n";
  EXPECT_EQ(outcome_of(ply).error,
            "t.ply: the file ends before all data: the header declares 4000000000 face elements (the file is "
            "truncated) (face 1)");
}

}  // namespace
}  // namespace convray::mesh
