// Wavefront OBJ: the lines that make geometry, read by the specification (Wavefront's
// "Object Files (.obj)", Appendix B1 of the Advanced Visualizer manual):
//
//   v x y [z [w]]          a vertex; z = 0 when missing (2D files); w, a weight for rational
//                          curves and surfaces, is ignored, as are colours after it
//   f c1 c2 c3 ...         a polygon; each corner v, v/vt, v//vn or v/vt/vn (an empty vt or vn
//                          after its slash is accepted too: v/, v//, v/vt/)
//   l c1 c2 ...            a polyline (corners v or v/vt): segments between consecutive corners
//   p v1 v2 ...            points
//
// Indices count from 1; negative ones count back from the last vertex read. A line ending in
// a backslash continues on the next. `#` starts a comment. Every other statement (vt, vn,
// g, o, s, usemtl, mtllib, curves and surfaces, ...) is skipped. Text is UTF-8, or UTF-16
// with a byte-order mark (src/mesh/text_encoding.hpp). Coordinates are correctly rounded
// doubles.
#include <cmath>
#include <cstdio>
#include <limits>

#include "mesh/load_error.hpp"
#include "mesh/readers.hpp"
#include "mesh/text_encoding.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

constexpr int64_t kMaxObjIndex = std::numeric_limits<uint32_t>::max();

// Physical lines joined where one ends in a backslash.
class ObjLines {
 public:
  explicit ObjLines(std::string_view text) : lines_(text) {}

  // The next logical line; `number` is the line it starts on.
  bool next(std::string_view& line, int& number) {
    if (!lines_.next(line)) return false;
    number = lines_.line_number();
    if (!continues(line)) return true;
    joined_.clear();
    std::string_view more = line;
    while (continues(more)) {
      joined_.append(without_backslash(more));
      joined_ += ' ';
      if (!lines_.next(more)) more = {};
    }
    joined_.append(more);
    line = joined_;
    return true;
  }

 private:
  static bool continues(std::string_view line) {
    line = trim_blanks(line);
    return !line.empty() && line.back() == '\\';
  }
  static std::string_view without_backslash(std::string_view line) {
    line = trim_blanks(line);
    return line.substr(0, line.size() - 1);
  }

  LineReader lines_;
  std::string joined_;
};

// A statement's tokens, up to a comment.
bool next_value(TokenReader& tokens, std::string_view& token) { return tokens.next(token) && token.front() != '#'; }

class ObjReader {
 public:
  ObjReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  PolygonMesh read() {
    reject_binary_bytes();
    ObjLines lines(text_);
    std::string_view line;
    while (lines.next(line, line_)) {
      TokenReader tokens(line);
      std::string_view keyword;
      if (!tokens.next(keyword)) continue;
      if (keyword == "v") read_vertex(tokens);
      else if (keyword == "f") read_face(tokens);
      else if (keyword == "l") read_line(tokens);
      else if (keyword == "p") read_points(tokens);
    }
    check_forward_references();
    mesh_.format = "OBJ";
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail_here(const std::string& what) { fail(file_, what, line_); }

  void reject_binary_bytes() {
    size_t at = find_binary_byte(text_);
    if (at == std::string_view::npos) return;
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(text_[at]));
    fail(file_, std::string("the file contains the control byte ") + byte + " at offset " + std::to_string(at) +
                    ", which has no place in an OBJ (text) file");
  }

  void read_vertex(TokenReader& tokens) {
    size_t v = mesh_.vertices.size();
    Vec3 position(0.0);
    int axis = 0;
    std::string_view token;
    for (; axis < 3 && next_value(tokens, token); ++axis) {
      double value = 0.0;
      if (!parse_real(token, value))
        fail_here("vertex coordinate " + quote_token(token) + " is not a number" + in_vertex(v));
      if (!std::isfinite(value)) fail_here("vertex has a non-finite coordinate " + quote_token(token) + in_vertex(v));
      position[axis] = value;
    }
    if (axis < 2)
      fail_here("vertex has " + std::to_string(axis) + " coordinate" + (axis == 1 ? "" : "s") +
                "; at least 2 are needed" + in_vertex(v));
    mesh_.vertices.push_back(position);
  }

  void read_face(TokenReader& tokens) {
    size_t f = mesh_.face_count();
    read_corners(tokens, "face", f, true);
    if (corners_.size() < 3)
      fail_here("face has " + std::to_string(corners_.size()) + " corners; at least 3 are needed" + in_face(f));
    mesh_.add_face(corners_);
    face_lines_.push_back(line_);
  }

  void read_line(TokenReader& tokens) {
    size_t l = mesh_.lines.size();
    read_corners(tokens, "line", l, false);
    if (corners_.size() < 2)
      fail_here("line has " + std::to_string(corners_.size()) + " corner" + (corners_.size() == 1 ? "" : "s") +
                "; at least 2 are needed" + in_line(l));
    mesh_.lines.add(corners_);
    line_lines_.push_back(line_);
  }

  void read_points(TokenReader& tokens) {
    std::string_view token;
    size_t before = mesh_.points.size();
    while (next_value(tokens, token)) {
      mesh_.points.push_back(read_index(token, token, "point", kNoElement));
      point_lines_.push_back(line_);
    }
    if (mesh_.points.size() == before) fail_here("'p' names no vertex");
  }

  // `kind` is "face" or "line", `element` its number.
  void read_corners(TokenReader& tokens, const char* kind, size_t element, bool normals) {
    corners_.clear();
    std::string_view token;
    while (next_value(tokens, token)) {
      size_t slash = token.find('/');
      corners_.push_back(read_index(token.substr(0, slash), token, kind, element));
      if (slash != std::string_view::npos) check_attributes(token, token.substr(slash + 1), kind, element, normals);
    }
  }

  // Returns the 0-based vertex index; positive ones are checked against the final vertex
  // count at the end, since they may point forward.
  // `text` is the index part of `token`.
  int64_t read_index(std::string_view text, std::string_view token, const char* kind, size_t element) {
    int64_t index = 0;
    if (!parse_integer(text, index) || index == 0 || index < -kMaxObjIndex || index > kMaxObjIndex)
      fail_here(std::string(kind) + (kind == std::string_view("point") ? " index " : " corner ") + quote_token(token) +
                " does not start with a vertex index (a non-zero integer; OBJ counts from 1)" + where(kind, element));
    if (index > 0) {
      max_index_ = std::max(max_index_, index - 1);
      return index - 1;
    }
    int64_t resolved = static_cast<int64_t>(mesh_.vertices.size()) + index;
    if (resolved < 0)
      fail_here(std::string(kind) + " refers to vertex " + std::to_string(index) + ", but only " + std::to_string(mesh_.vertices.size()) +
                " vertices precede it" + where(kind, element));
    return resolved;
  }

  // The texture and normal indices are not used, but must be well formed: empty or a
  // non-zero integer, at most two slashes (one for polylines, which have no normals).
  void check_attributes(std::string_view token, std::string_view rest, const char* kind, size_t element, bool normals) {
    size_t slash = rest.find('/');
    std::string_view texture = rest.substr(0, slash);
    std::string_view normal = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);
    bool ok = is_attribute(texture) && is_attribute(normal) && normal.find('/') == std::string_view::npos &&
              (normals || normal.empty());
    if (!ok)
      fail_here(std::string(normals ? "face" : "line") + " corner " + quote_token(token) + " is not of the form " +
                (normals ? "v, v/vt, v//vn or v/vt/vn" : "v or v/vt") + where(kind, element));
  }

  // " (face 3)", " (line 0)"; nothing for points, which are not counted.
  static constexpr size_t kNoElement = SIZE_MAX;
  static std::string where(const char* kind, size_t element) {
    return element == kNoElement ? "" : " (" + std::string(kind) + " " + std::to_string(element) + ")";
  }

  static bool is_attribute(std::string_view part) {
    int64_t index = 0;
    return part.empty() || (parse_integer(part, index) && index != 0 && index >= -kMaxObjIndex && index <= kMaxObjIndex);
  }

  void check_forward_references() {
    const auto count = static_cast<int64_t>(mesh_.vertices.size());
    if (max_index_ < count) return;
    check_lists(mesh_.faces, face_lines_, "face", count);
    check_lists(mesh_.lines, line_lines_, "line", count);
    for (size_t k = 0; k < mesh_.points.size(); ++k) {
      if (mesh_.points[k] >= count) fail_unknown_vertex("point", mesh_.points[k], count, "", point_lines_[k]);
    }
  }

  void check_lists(const IndexLists& lists, const std::vector<int>& lines, const std::string& what, int64_t count) {
    for (size_t i = 0; i < lists.size(); ++i) {
      for (int64_t index : lists[i]) {
        if (index >= count) fail_unknown_vertex(what, index, count, " (" + what + " " + std::to_string(i) + ")", lines[i]);
      }
    }
  }

  [[noreturn]] void fail_unknown_vertex(const std::string& what, int64_t index, int64_t count, const std::string& where,
                                        int line) {
    fail(file_, what + " refers to vertex " + std::to_string(index + 1) + ", but the file has " + std::to_string(count) +
                    " vertices" + where, line);
  }

  std::string_view text_;
  const std::string& file_;
  PolygonMesh mesh_;
  std::vector<int> face_lines_, line_lines_, point_lines_;  // where each was written
  std::vector<int64_t> corners_;
  int64_t max_index_ = -1;  // the largest positive index seen, counted from 0
  int line_ = 0;
};

}  // namespace

PolygonMesh read_obj(std::string_view bytes, const std::string& file) {
  std::string converted;
  return ObjReader(as_utf8(bytes, converted, file), file).read();
}

}  // namespace convray::mesh
