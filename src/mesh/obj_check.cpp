#include "mesh/obj_check.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "mesh/load_error.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

constexpr int64_t kMaxObjIndex = std::numeric_limits<int32_t>::max();  // tinyobjloader uses int
constexpr size_t kMaxObjCorners = 255;  // tinyobjloader stores corner counts in a byte

class ObjScanner {
 public:
  ObjScanner(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  PolygonMesh scan() {
    reject_binary_bytes();
    LineReader lines(text_);
    std::string_view line;
    while (lines.next(line)) {
      line_ = lines.line_number();
      TokenReader tokens(line);
      std::string_view keyword;
      if (!tokens.next(keyword)) continue;
      if (keyword == "v") read_vertex(tokens);
      if (keyword == "f") read_face(tokens);
    }
    check_forward_references();
    mesh_.format = "OBJ";
    return std::move(mesh_);
  }

 private:
  void reject_binary_bytes() {
    size_t at = find_binary_byte(text_);
    if (at == std::string_view::npos) return;
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(text_[at]));
    fail(file_, std::string("the file contains the control byte ") + byte + " at offset " +
                    std::to_string(at) + ", which has no place in an OBJ (text) file");
  }

  void read_vertex(TokenReader& tokens) {
    size_t v = mesh_.vertices.size();
    Vec3 position;
    for (int axis = 0; axis < 3; ++axis) {
      std::string_view token;
      if (!tokens.next(token))
        fail(file_, "vertex has " + std::to_string(axis) + " coordinates; 3 are needed" + in_vertex(v), line_);
      double value = 0.0;
      if (!parse_real(token, value))
        fail(file_, "vertex coordinate " + quote_token(token) + " is not a number" + in_vertex(v), line_);
      if (!std::isfinite(value))
        fail(file_, "vertex has a non-finite coordinate " + quote_token(token) + in_vertex(v), line_);
      position[axis] = value;
    }
    mesh_.vertices.push_back(position);  // a fourth value (w) or colours may follow; unused
  }

  void read_face(TokenReader& tokens) {
    size_t f = mesh_.face_count();
    corners_.clear();
    std::string_view token;
    while (tokens.next(token)) corners_.push_back(read_corner(token, f));
    if (corners_.size() < 3)
      fail(file_, "face has " + std::to_string(corners_.size()) + " corners; at least 3 are needed" + in_face(f),
           line_);
    if (corners_.size() > kMaxObjCorners)
      fail(file_, "face has " + std::to_string(corners_.size()) + " corners; the OBJ reader handles at most " +
                      std::to_string(kMaxObjCorners) + in_face(f),
           line_);
    mesh_.add_face(corners_);
    face_lines_.push_back(line_);
  }

  // "v", "v/vt", "v//vn" or "v/vt/vn"; returns the 0-based vertex index.
  int64_t read_corner(std::string_view token, size_t f) {
    size_t slash = token.find('/');
    std::string_view vertex_part = token.substr(0, slash);
    int64_t index = 0;
    if (!parse_integer(vertex_part, index) || index == 0 || index < -kMaxObjIndex || index > kMaxObjIndex)
      fail(file_, "face corner " + quote_token(token) +
                      " does not start with a vertex index (a non-zero integer; OBJ counts from 1)" + in_face(f),
           line_);
    if (slash != std::string_view::npos) check_attribute_indices(token, token.substr(slash + 1), f);
    if (index > 0) return index - 1;  // checked against the final vertex count at the end
    int64_t resolved = static_cast<int64_t>(mesh_.vertices.size()) + index;
    if (resolved < 0)
      fail(file_, "face refers to vertex " + std::to_string(index) + ", but only " +
                      std::to_string(mesh_.vertices.size()) + " vertices precede it" + in_face(f),
           line_);
    return resolved;
  }

  // The texture and normal indices are not used, but tinyobjloader rejects malformed ones;
  // catching them here gives the better message.
  void check_attribute_indices(std::string_view token, std::string_view rest, size_t f) {
    size_t slash = rest.find('/');
    std::string_view texture = rest.substr(0, slash);
    std::string_view normal = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);
    bool texture_ok = texture.empty() ? slash != std::string_view::npos : is_attribute_index(texture);
    bool normal_ok = slash == std::string_view::npos || is_attribute_index(normal);
    if (!texture_ok || !normal_ok)
      fail(file_, "face corner " + quote_token(token) + " is not of the form v, v/vt, v//vn or v/vt/vn" + in_face(f),
           line_);
  }

  static bool is_attribute_index(std::string_view part) {
    int64_t index = 0;
    return parse_integer(part, index) && index != 0 && index >= -kMaxObjIndex && index <= kMaxObjIndex;
  }

  // Positive indices may point forward in the file, so they are checked once all vertices
  // are known.
  void check_forward_references() {
    const int64_t count = static_cast<int64_t>(mesh_.vertices.size());
    for (size_t f = 0; f < mesh_.face_count(); ++f) {
      for (int64_t index : mesh_.face(f)) {
        if (index >= count)
          fail(file_, "face refers to vertex " + std::to_string(index + 1) + ", but the file has " +
                          std::to_string(count) + " vertices" + in_face(f),
               face_lines_[f]);
      }
    }
  }

  std::string_view text_;
  const std::string& file_;
  PolygonMesh mesh_;
  std::vector<int> face_lines_;
  std::vector<int64_t> corners_;
  int line_ = 0;
};

}  // namespace

PolygonMesh scan_obj(std::string_view text, const std::string& file) { return ObjScanner(text, file).scan(); }

}  // namespace convray::mesh
