#include "mesh/off_binary.hpp"

#include <bit>
#include <cmath>
#include <exception>

#include "mesh/load_error.hpp"

namespace convray::mesh {
namespace {

// One way of writing binary OFF.
struct Dialect {
  bool big_endian;
  bool colour_counts;  // each face ends with a colour count and that many floats
  const char* name;
};

const Dialect kDialects[] = {
    {true, true, "OFF binary"},
    {false, false, "OFF binary (little-endian, no face colours)"},
    {true, false, "OFF binary (no face colours)"},
    {false, true, "OFF binary (little-endian)"},
};

// 32-bit words in one byte order, each checked to be there.
class Words {
 public:
  Words(std::string_view bytes, size_t offset, bool big_endian, const std::string& file)
      : bytes_(bytes), offset_(offset), big_endian_(big_endian), file_(file) {}

  uint32_t word(const std::string& where) {
    if (remaining() < 1) fail(file_, "the binary OFF data ends early (the file is truncated)" + where);
    const auto* b = reinterpret_cast<const unsigned char*>(bytes_.data() + offset_);
    offset_ += 4;
    if (big_endian_) return uint32_t{b[0]} << 24 | uint32_t{b[1]} << 16 | uint32_t{b[2]} << 8 | uint32_t{b[3]};
    return uint32_t{b[3]} << 24 | uint32_t{b[2]} << 16 | uint32_t{b[1]} << 8 | uint32_t{b[0]};
  }
  int32_t integer(const std::string& where) { return static_cast<int32_t>(word(where)); }
  float real(const std::string& where) { return std::bit_cast<float>(word(where)); }
  void skip(uint64_t words, const std::string& where) {
    if (words > remaining()) fail(file_, "the binary OFF data ends early (the file is truncated)" + where);
    offset_ += static_cast<size_t>(4 * words);
  }
  uint64_t remaining() const { return (bytes_.size() - offset_) / 4; }
  std::string_view rest() const { return bytes_.substr(offset_); }

 private:
  std::string_view bytes_;
  size_t offset_;
  bool big_endian_;
  const std::string& file_;
};

class BinaryOffReader {
 public:
  BinaryOffReader(std::string_view bytes, size_t start, const OffLayout& layout, const Dialect& dialect,
                  const std::string& file)
      : in_(bytes, start, dialect.big_endian, file), layout_(layout), dialect_(dialect), file_(file) {}

  PolygonMesh read() {
    if (layout_.dimension) fail(file_, "binary nOFF is not supported");
    mesh_.format = dialect_.name;
    const int32_t vertices = in_.integer(" (header)"), faces = in_.integer(" (header)");
    in_.integer(" (header)");  // edges
    if (vertices < 0 || faces < 0) fail(file_, "the binary OFF header has a negative count");
    const auto vertex_count = static_cast<uint64_t>(vertices);
    if (vertex_count > in_.remaining() / layout_.floats_per_vertex())
      fail(file_, "the binary OFF data ends before its " + std::to_string(vertex_count) +
                      " vertices (the file is truncated)");
    mesh_.vertices.reserve(vertex_count);
    for (uint64_t v = 0; v < vertex_count; ++v) read_vertex(v);
    for (uint64_t f = 0; f < static_cast<uint64_t>(faces); ++f) read_face(f, vertex_count);
    for (char c : in_.rest()) {
      if (c != '\n' && c != '\r' && c != ' ' && c != '\t' && c != '\0')
        fail(file_, "the binary OFF data goes on after its " + std::to_string(faces) + " faces");
    }
    return std::move(mesh_);
  }

 private:
  void read_vertex(uint64_t v) {
    double values[4] = {0.0, 0.0, 0.0, 1.0};
    for (int k = 0; k < layout_.coordinates(); ++k) values[k] = in_.real(in_vertex(v));
    in_.skip(layout_.floats_per_vertex() - static_cast<uint64_t>(layout_.coordinates()), in_vertex(v));
    if (!std::isfinite(values[0] + values[1] + values[2] + values[3]))
      fail(file_, "vertex has a non-finite coordinate" + in_vertex(v));
    if (values[3] == 0.0) fail(file_, "4OFF vertex with w = 0 (a point at infinity)" + in_vertex(v));
    mesh_.vertices.emplace_back(values[0] / values[3], values[1] / values[3], values[2] / values[3]);
  }

  void read_face(uint64_t f, uint64_t vertex_count) {
    const int32_t corner_count = in_.integer(in_face(f));
    if (corner_count < 3)
      fail(file_, "face has " + std::to_string(corner_count) + " corners; at least 3 are needed" + in_face(f));
    if (static_cast<uint64_t>(corner_count) > in_.remaining())
      fail(file_, "the binary OFF data ends early (the file is truncated)" + in_face(f));
    corners_.clear();
    for (int32_t k = 0; k < corner_count; ++k) {
      const int32_t index = in_.integer(in_face(f));
      if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
        fail(file_, "face refers to vertex " + std::to_string(index) + ", but the file has " +
                        std::to_string(vertex_count) + " vertices" + in_face(f));
      corners_.push_back(index);
    }
    if (dialect_.colour_counts) {
      const int32_t colours = in_.integer(in_face(f));
      if (colours < 0) fail(file_, "face has a negative colour count" + in_face(f));
      in_.skip(static_cast<uint64_t>(colours), in_face(f));
    }
    mesh_.add_face(corners_);
  }

  Words in_;
  const OffLayout& layout_;
  const Dialect& dialect_;
  const std::string& file_;
  PolygonMesh mesh_;
  std::vector<int64_t> corners_;
};

}  // namespace

PolygonMesh read_binary_off(std::string_view bytes, size_t start, const OffLayout& layout, const std::string& file) {
  std::exception_ptr first_error;
  for (const Dialect& dialect : kDialects) {
    try {
      return BinaryOffReader(bytes, start, layout, dialect, file).read();
    } catch (const InputError&) {
      if (!first_error) first_error = std::current_exception();
    }
  }
  std::rethrow_exception(first_error);
}

}  // namespace convray::mesh
