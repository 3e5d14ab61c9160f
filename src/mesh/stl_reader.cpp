// STL, text and binary. Binary: an 80-byte header of anything, a little-endian uint32
// triangle count, then 50 bytes per triangle (normal, three corners as float32, two bytes
// of attributes); the file is binary when its size is exactly 84 + 50 x count. Text: `solid
// NAME`, facets (`facet normal n n n`, `outer loop`, three `vertex x y z`, `endloop`,
// `endfacet`), `endsolid`; any number of solids, empty ones included, one after the other.
// A text file that starts with "solid" but whose size fits its count is binary: binary headers
// often start with "solid" too. A binary file longer than its count says is read, the bytes
// after its triangles ignored; a text file may end without its last `endsolid` (OpenMesh
// writes such files), but not in the middle of a facet.
//
// Every corner is its own vertex (STL shares none); the normals are not read: the
// triangles' winding says which side is out.
#include <array>
#include <cctype>
#include <cstring>

#include "mesh/load_error.hpp"
#include "mesh/readers.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

constexpr uint64_t kBinaryHeaderSize = 84;  // 80 bytes of anything, then a uint32 count
constexpr uint64_t kBinaryTriangleSize = 50;

uint32_t little_endian_uint32(const char* at) {
  const auto* b = reinterpret_cast<const unsigned char*>(at);
  return uint32_t{b[0]} | uint32_t{b[1]} << 8 | uint32_t{b[2]} << 16 | uint32_t{b[3]} << 24;
}

float little_endian_float(const char* at) {
  uint32_t bits = little_endian_uint32(at);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

uint32_t binary_triangle_count(std::string_view bytes) { return little_endian_uint32(bytes.data() + 80); }

PolygonMesh read_binary(std::string_view bytes, uint64_t triangle_count) {
  PolygonMesh mesh;
  mesh.format = "STL binary";
  mesh.vertex_per_corner = true;
  mesh.vertices.reserve(3 * triangle_count);
  for (uint64_t t = 0; t < triangle_count; ++t) {
    const char* corners = bytes.data() + kBinaryHeaderSize + kBinaryTriangleSize * t + 12;  // after the normal
    for (int k = 0; k < 3; ++k) {
      const char* at = corners + 12 * k;
      mesh.vertices.emplace_back(little_endian_float(at), little_endian_float(at + 4), little_endian_float(at + 8));
    }
    const int64_t first = static_cast<int64_t>(3 * t);
    const int64_t face[3] = {first, first + 1, first + 2};
    mesh.add_face(face);
  }
  return mesh;
}

size_t skip_white(std::string_view bytes, size_t at) {
  while (at < bytes.size() && (is_blank(bytes[at]) || is_line_end(bytes[at]))) ++at;
  return at;
}

// Whitespace-separated tokens across lines, with the line each is on.
class Tokens {
 public:
  explicit Tokens(std::string_view text) : text_(text) {}

  bool next(std::string_view& token) {
    while (offset_ < text_.size() && (is_blank(text_[offset_]) || is_line_end(text_[offset_]))) step();
    if (offset_ >= text_.size()) return false;
    size_t end = offset_;
    while (end < text_.size() && !is_blank(text_[end]) && !is_line_end(text_[end])) ++end;
    token = text_.substr(offset_, end - offset_);
    offset_ = end;
    return true;
  }
  // The next token if it is on the current line (assimp reads the numbers after `normal` and
  // `vertex` skipping blanks only).
  bool next_on_line(std::string_view& token) {
    while (offset_ < text_.size() && is_blank(text_[offset_])) ++offset_;
    if (offset_ >= text_.size() || is_line_end(text_[offset_])) return false;
    return next(token);
  }
  // The rest of the current line, as tokens the caller looks at one by one.
  std::string_view rest_of_line() {
    size_t end = offset_;
    while (end < text_.size() && !is_line_end(text_[end])) ++end;
    std::string_view rest = text_.substr(offset_, end - offset_);
    offset_ = end;
    return rest;
  }
  int line() const { return line_; }

 private:
  void step() {
    char c = text_[offset_++];
    if (c == '\n' || (c == '\r' && (offset_ >= text_.size() || text_[offset_] != '\n'))) ++line_;
  }

  std::string_view text_;
  size_t offset_ = 0;
  int line_ = 1;
};

// Keywords in any case: some CAD exporters write SOLID, FACET NORMAL, ...
bool is(std::string_view token, std::string_view keyword) {
  if (token.size() != keyword.size()) return false;
  for (size_t i = 0; i < token.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(token[i])) != keyword[i]) return false;
  }
  return true;
}

bool starts_with_endsolid(std::string_view token) { return is(token.substr(0, 8), "endsolid"); }

bool is_keyword(std::string_view token) {
  for (std::string_view keyword : {"facet", "normal", "outer", "loop", "vertex", "endloop", "endfacet", "solid"}) {
    if (is(token, keyword)) return true;
  }
  return starts_with_endsolid(token);
}

class AsciiStlReader {
 public:
  AsciiStlReader(std::string_view text, const std::string& file) : tokens_(text), file_(file) {
    mesh_.format = "STL ascii";
    mesh_.vertex_per_corner = true;
  }

  PolygonMesh read() {
    std::string_view token;
    while (tokens_.next(token)) {
      if (!is(token, "solid")) fail_here("expected 'solid' but found " + quote_token(token));
      read_solid_name();
      while (read_facet_or_end()) ++facets_;
    }
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail_here(const std::string& what) { fail(file_, "ASCII STL: " + what, tokens_.line()); }

  // `solid` may be followed by a name of any words, as long as none of them is a keyword:
  // a facet on the `solid` line is a file we would misread.
  void read_solid_name() {
    TokenReader words(tokens_.rest_of_line());
    std::string_view word;
    while (words.next(word)) {
      if (is_keyword(word)) fail_here("the solid's name contains the keyword " + quote_token(word));
    }
  }

  // One facet; false at `endsolid`, or at the end of the file between facets (OpenMesh's
  // writer, among others, leaves the last `endsolid` out).
  bool read_facet_or_end() {
    std::string_view token;
    if (!tokens_.next(token)) return false;
    if (starts_with_endsolid(token)) {
      if (!is(token, "endsolid")) fail_here("expected 'endsolid' but found " + quote_token(token));
      tokens_.rest_of_line();  // the solid's name again, ignored
      return false;
    }
    if (!is(token, "facet")) fail_here("expected 'facet' or 'endsolid' but found " + quote_token(token) + in_face(facets_));
    expect_on_line("normal");
    read_numbers();
    expect("outer");
    expect("loop");
    for (int corner = 0; corner < 3; ++corner) {
      expect("vertex");
      mesh_.vertices.push_back(read_numbers());
    }
    expect("endloop");
    expect("endfacet");
    const int64_t first = static_cast<int64_t>(3 * facets_);
    const int64_t face[3] = {first, first + 1, first + 2};
    mesh_.add_face(face);
    return true;
  }

  void expect(std::string_view keyword) {
    std::string_view token = next_or_truncated();
    if (!is(token, keyword))
      fail_here("expected '" + std::string(keyword) + "' but found " + quote_token(token) + in_face(facets_));
  }

  void expect_on_line(std::string_view keyword) {
    std::string_view token;
    if (!tokens_.next_on_line(token) || !is(token, keyword))
      fail_here("expected '" + std::string(keyword) + "' on the same line" + in_face(facets_));
  }

  // Three numbers on the line of the keyword before them.
  Vec3 read_numbers() {
    Vec3 numbers;
    for (int axis = 0; axis < 3; ++axis) {
      std::string_view token;
      if (!tokens_.next_on_line(token)) fail_here("expected three numbers on the line" + in_face(facets_));
      if (!parse_real(token, numbers[axis]))
        fail_here("expected a number but found " + quote_token(token) + in_face(facets_));
    }
    return numbers;
  }

  std::string_view next_or_truncated() {
    std::string_view token;
    if (!tokens_.next(token)) fail(file_, "ASCII STL: the file ends before 'endsolid' (the file is truncated)" + in_face(facets_));
    return token;
  }

  Tokens tokens_;
  const std::string& file_;
  uint64_t facets_ = 0;
  PolygonMesh mesh_;
};

}  // namespace

PolygonMesh read_stl(std::string_view bytes, const std::string& file) {
  uint64_t size = bytes.size();
  uint32_t count = 0;
  if (size >= kBinaryHeaderSize) {
    count = binary_triangle_count(bytes);
    if (kBinaryHeaderSize + kBinaryTriangleSize * count == size) return read_binary(bytes, count);
  }
  const uint64_t expected = kBinaryHeaderSize + kBinaryTriangleSize * uint64_t{count};
  size_t start = skip_white(bytes, 0);
  if (is(bytes.substr(start, 5), "solid") && bytes.find('\0') == std::string_view::npos) {
    size_t at = find_binary_byte(bytes);
    if (at != std::string_view::npos) fail(file, "the ASCII STL contains a control byte at offset " + std::to_string(at));
    return AsciiStlReader(bytes.substr(start), file).read();
  }
  if (size < kBinaryHeaderSize)
    fail(file, "not an STL file: too short for a binary STL (" + std::to_string(size) +
                   " bytes, the header alone is 84) and not ASCII STL (it does not start with 'solid')");
  // Bytes after the triangles the count declares are ignored, as after PLY's declared data.
  if (size > expected) return read_binary(bytes, count);
  fail(file, "binary STL of the wrong size: the header declares " + std::to_string(count) +
                 " triangles, which take 84 + 50 x " + std::to_string(count) + " = " +
                 std::to_string(expected) + " bytes, but the file has " + std::to_string(size) + " bytes" +
                 (size < expected ? " (the file is truncated)" : ""));
}

}  // namespace convray::mesh
