// OFF as Geomview defines it (and Princeton's shape benchmarks and ModelNet write it):
//
//   [ST][C][N][4][n]OFF [BINARY]   the keyword; its prefixes say what each vertex carries
//   [Ndim]                          nOFF only: the dimension, which must be 3 here
//   NVertices NFaces [NEdges]       (NEdges is not used)
//   x y z [w] [normal] [colour] [texture]       one vertex after the other
//   N i1 ... iN [colour]                        one face after the other
//
// Text OFF is whitespace-separated, not line-based: the values a vertex or a face needs may
// continue on the next lines, and the counts may be glued to the keyword (`OFF8 6 12`, as in
// ModelNet). What follows those values on their last line (normals, colours, texture
// coordinates) is skipped. `#` starts a comment that runs to the end of its line. 4OFF's
// fourth coordinate w divides the other three. A file with no faces is a point cloud.
//
// Binary OFF (`OFF BINARY`) is read by src/mesh/off_binary.cpp.
#include <cmath>

#include "mesh/load_error.hpp"
#include "mesh/off_binary.hpp"
#include "mesh/readers.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

constexpr uint64_t kMaxCount = 0xffffffffu;

struct OffCounts {
  uint64_t vertices = 0, faces = 0;
};

// Whitespace-separated tokens with `#` comments, and the line each starts on.
class OffTokens {
 public:
  explicit OffTokens(std::string_view text) : text_(text) {}

  bool next(std::string_view& token) {
    skip_space();
    if (offset_ >= text_.size()) return false;
    token_line_ = line_;
    size_t end = offset_;
    while (end < text_.size() && !is_space(text_[end]) && text_[end] != '#') ++end;
    token = text_.substr(offset_, end - offset_);
    offset_ = end;
    return true;
  }
  // Whether another token follows on the line of the last one.
  bool more_on_line() {
    while (offset_ < text_.size() && is_blank(text_[offset_])) ++offset_;
    return offset_ < text_.size() && !is_line_end(text_[offset_]) && text_[offset_] != '#';
  }
  void skip_rest_of_line() {
    while (offset_ < text_.size() && !is_line_end(text_[offset_])) ++offset_;
  }
  // Past the end of the current line: where binary data starts.
  size_t start_of_next_line() {
    skip_rest_of_line();
    if (offset_ < text_.size() && text_[offset_] == '\r') ++offset_;
    if (offset_ < text_.size() && text_[offset_] == '\n') ++offset_;
    return offset_;
  }
  int line() const { return token_line_; }
  size_t remaining() const { return text_.size() - offset_; }

 private:
  static bool is_space(char c) { return is_blank(c) || is_line_end(c); }

  void skip_space() {
    while (offset_ < text_.size()) {
      char c = text_[offset_];
      if (c == '#') {
        skip_rest_of_line();
      } else if (c == '\n' || (c == '\r' && (offset_ + 1 >= text_.size() || text_[offset_ + 1] != '\n'))) {
        ++line_, ++offset_;  // "\n", "\r\n" and a lone "\r" end one line each
      } else if (is_space(c)) {
        ++offset_;
      } else {
        return;
      }
    }
  }

  std::string_view text_;
  size_t offset_ = 0;
  int line_ = 1;
  int token_line_ = 1;
};

class OffReader {
 public:
  OffReader(std::string_view bytes, const std::string& file) : bytes_(bytes), tokens_(bytes), file_(file) {}

  PolygonMesh read() {
    std::string_view glued = read_keyword();
    if (layout_.binary) return read_binary_off(bytes_, tokens_.start_of_next_line(), layout_, file_);
    reject_control_bytes();
    if (layout_.dimension) read_dimension(glued);
    OffCounts counts = read_counts(layout_.dimension ? std::string_view() : glued);
    mesh_.format = "OFF";
    mesh_.vertices.reserve(std::min<uint64_t>(counts.vertices, tokens_.remaining() / 2 + 1));
    for (uint64_t v = 0; v < counts.vertices; ++v) read_vertex(v, counts.vertices);
    for (uint64_t f = 0; f < counts.faces; ++f) read_face(f, counts);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail_at_token(const std::string& what) { fail(file_, what, tokens_.line()); }

  // The keyword, its prefixes, and BINARY after it; returns what is glued to "OFF".
  std::string_view read_keyword() {
    std::string_view keyword;
    if (!tokens_.next(keyword) || keyword.find("OFF") == std::string_view::npos)
      fail(file_, "not an OFF file: it does not start with the keyword OFF (or COFF, NOFF, STOFF, 4OFF, ...)",
           tokens_.line());
    std::string_view rest = keyword;
    auto take = [&rest](std::string_view prefix) {
      if (rest.substr(0, prefix.size()) != prefix) return false;
      rest.remove_prefix(prefix.size());
      return true;
    };
    layout_.texture = take("ST");
    layout_.colour = take("C");
    layout_.normal = take("N");
    layout_.homogeneous = take("4");
    layout_.dimension = take("n");
    if (!take("OFF"))
      fail_at_token("not an OFF file: it does not start with the keyword OFF (or COFF, NOFF, STOFF, 4OFF, ...)");
    std::string_view binary;
    if (rest.empty() && tokens_.more_on_line()) {
      OffTokens peek = tokens_;
      if (peek.next(binary) && binary == "BINARY") {
        tokens_ = peek;
        layout_.binary = true;
      }
    }
    return rest;
  }

  void reject_control_bytes() {
    size_t at = find_binary_byte(bytes_);
    if (at != std::string_view::npos)
      fail(file_, "the file contains a control byte at offset " + std::to_string(at) +
                      ", which has no place in an OFF text file (binary OFF starts with 'OFF BINARY')");
  }

  void read_dimension(std::string_view glued) {
    std::string_view token = glued;
    if (token.empty() && !tokens_.next(token)) fail(file_, "the nOFF header ends before its dimension");
    uint64_t dimension = 0;
    if (!parse_digits(token, dimension)) fail_at_token("the nOFF dimension " + quote_token(token) + " is not a whole number");
    if (dimension != 3)
      fail_at_token("nOFF of dimension " + std::to_string(dimension) + ": only 3-dimensional vertices are supported");
  }

  OffCounts read_counts(std::string_view glued) {
    OffCounts counts;
    counts.vertices = glued.empty() ? read_count("vertex") : parse_count(glued, "vertex");
    counts.faces = read_count("face");
    if (tokens_.more_on_line()) read_count("edge");  // the edge count is optional and unused
    return counts;
  }

  uint64_t read_count(const char* what) {
    std::string_view token;
    if (!tokens_.next(token))
      fail(file_, std::string("the OFF header ends before its ") + what + " count (the file is truncated)");
    return parse_count(token, what);
  }

  uint64_t parse_count(std::string_view token, const char* what) {
    uint64_t count = 0;
    if (!parse_digits(token, count) || count > kMaxCount)
      fail_at_token(std::string("the OFF ") + what + " count " + quote_token(token) + " is not a whole number below 2^32");
    return count;
  }

  void read_vertex(uint64_t v, uint64_t count) {
    double values[4] = {0.0, 0.0, 0.0, 1.0};
    for (int k = 0; k < layout_.coordinates(); ++k) {
      std::string_view token;
      if (!tokens_.next(token))
        fail(file_, "the file ends after " + std::to_string(v) + " of the " + std::to_string(count) +
                        " vertices the header declares (the file is truncated)" + in_vertex(v));
      if (!parse_real(token, values[k]))
        fail_at_token("vertex value " + quote_token(token) + " is not a number" + in_vertex(v));
      if (!std::isfinite(values[k]))
        fail_at_token("vertex has a non-finite coordinate " + quote_token(token) + in_vertex(v));
    }
    tokens_.skip_rest_of_line();
    add_vertex(values, v);
  }

  void add_vertex(const double (&values)[4], uint64_t v) {
    if (values[3] == 0.0) fail_at_token("4OFF vertex with w = 0 (a point at infinity)" + in_vertex(v));
    mesh_.vertices.emplace_back(values[0] / values[3], values[1] / values[3], values[2] / values[3]);
  }

  void read_face(uint64_t f, const OffCounts& counts) {
    std::string_view token;
    if (!tokens_.next(token))
      fail(file_, "the file ends after " + std::to_string(f) + " of the " + std::to_string(counts.faces) +
                      " faces the header declares (the file is truncated)" + in_face(f));
    uint64_t corner_count = 0;
    if (!parse_digits(token, corner_count))
      fail_at_token("face does not start with its number of corners: found " + quote_token(token) + in_face(f));
    if (corner_count < 3)
      fail_at_token("face has " + std::to_string(corner_count) + " corners; at least 3 are needed" + in_face(f));
    corners_.clear();
    for (uint64_t k = 0; k < corner_count; ++k) corners_.push_back(read_index(f, corner_count, k, counts.vertices));
    tokens_.skip_rest_of_line();  // the face's colour
    mesh_.add_face(corners_);
  }

  int64_t read_index(uint64_t f, uint64_t corner_count, uint64_t k, uint64_t vertex_count) {
    std::string_view token;
    if (!tokens_.next(token))
      fail(file_, "the file ends in the middle of face " + std::to_string(f) + ": " + std::to_string(k) + " of its " +
                      std::to_string(corner_count) + " corners are there (the file is truncated)" + in_face(f));
    int64_t index = 0;
    if (!parse_integer(token, index)) fail_at_token("face index " + quote_token(token) + " is not a whole number" + in_face(f));
    if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
      fail_at_token("face refers to vertex " + std::to_string(index) + ", but the file has " +
                    std::to_string(vertex_count) + " vertices" + in_face(f));
    return index;
  }

  std::string_view bytes_;
  OffTokens tokens_;
  const std::string& file_;
  OffLayout layout_;
  PolygonMesh mesh_;
  std::vector<int64_t> corners_;
};

}  // namespace

PolygonMesh read_off(std::string_view bytes, const std::string& file) { return OffReader(bytes, file).read(); }

}  // namespace convray::mesh
