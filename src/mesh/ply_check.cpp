#include "mesh/ply_check.hpp"

#include <cstring>
#include <limits>

#include "mesh/load_error.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

// What the walk needs to know about the header, beyond the header itself.
struct Roles {
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  const PlyProperty* face_indices = nullptr;
};

Roles find_roles(const PlyHeader& header, const std::string& file) {
  Roles roles;
  roles.vertex = header.find("vertex");
  roles.face = header.find("face");
  if (!roles.vertex) fail(file, "the PLY header declares no 'vertex' element");
  if (!roles.face) fail(file, "the PLY header declares no 'face' element (a point cloud has no triangles)");
  if (header.find("tristrips")) fail(file, "PLY triangle strips (element 'tristrips') are not supported");
  for (const char* axis : {"x", "y", "z"}) {
    const PlyProperty* coordinate = roles.vertex->find(axis);
    if (!coordinate || coordinate->is_list)
      fail(file, std::string("the PLY vertex element has no scalar property '") + axis + "'");
  }
  const PlyProperty* indices = roles.face->find("vertex_indices");
  const PlyProperty* index = roles.face->find("vertex_index");
  if (indices && index) fail(file, "the PLY face element has both 'vertex_indices' and 'vertex_index'");
  roles.face_indices = indices ? indices : index;
  if (!roles.face_indices || !roles.face_indices->is_list || !is_integer(roles.face_indices->type))
    fail(file, "the PLY face element has no list of integer 'vertex_indices'");
  return roles;
}

int64_t integer_limit_low(PlyType type) {
  switch (type) {
    case PlyType::Int8: return std::numeric_limits<int8_t>::min();
    case PlyType::Int16: return std::numeric_limits<int16_t>::min();
    case PlyType::Int32: return std::numeric_limits<int32_t>::min();
    default: return 0;
  }
}

int64_t integer_limit_high(PlyType type) {
  switch (type) {
    case PlyType::Int8: return std::numeric_limits<int8_t>::max();
    case PlyType::UInt8: return std::numeric_limits<uint8_t>::max();
    case PlyType::Int16: return std::numeric_limits<int16_t>::max();
    case PlyType::UInt16: return std::numeric_limits<uint16_t>::max();
    case PlyType::Int32: return std::numeric_limits<int32_t>::max();
    default: return std::numeric_limits<uint32_t>::max();
  }
}

// Shared by both walks: what to do with one face once its indices are read.
class FaceCollector {
 public:
  FaceCollector(uint64_t vertex_count, const std::string& file) : vertex_count_(vertex_count), file_(file) {}

  void add(const std::vector<int64_t>& corners, size_t f, int line) {
    if (corners.size() < 3)
      fail(file_, "face has " + std::to_string(corners.size()) + " corners; at least 3 are needed" + in_face(f),
           line);
    for (int64_t index : corners) {
      if (index < 0 || static_cast<uint64_t>(index) >= vertex_count_)
        fail(file_, "face refers to vertex " + std::to_string(index) + ", but the file has " +
                        std::to_string(vertex_count_) + " vertices" + in_face(f),
             line);
    }
    faces_.add_face(corners);
  }
  PolygonMesh take() { return std::move(faces_); }

 private:
  uint64_t vertex_count_;
  const std::string& file_;
  PolygonMesh faces_;
};

std::string element_label(const PlyElement& element, uint64_t index) {
  if (element.name == "vertex") return in_vertex(index);
  if (element.name == "face") return in_face(index);
  return " (" + element.name + " " + std::to_string(index) + ")";
}

}  // namespace

// ---- Binary ---------------------------------------------------------------------------

namespace {

class BinaryWalk {
 public:
  BinaryWalk(std::string_view bytes, const PlyHeader& header, const Roles& roles, const std::string& file)
      : bytes_(bytes), offset_(header.body_offset), header_(header), roles_(roles), file_(file),
        faces_(roles.vertex->count, file) {}

  PolygonMesh walk() {
    for (const PlyElement& element : header_.elements) walk_element(element);
    return faces_.take();
  }

 private:
  void walk_element(const PlyElement& element) {
    bool has_list = false;
    size_t fixed_size = 0;
    for (const PlyProperty& property : element.properties) {
      has_list |= property.is_list;
      fixed_size += size_of(property.type);
    }
    if (!has_list && &element != roles_.face) return skip_fixed(element, fixed_size);
    for (uint64_t i = 0; i < element.count; ++i) walk_instance(element, i);
  }

  // Elements of fixed size are checked in one step: no loop over a count nobody has paid for.
  void skip_fixed(const PlyElement& element, size_t instance_size) {
    uint64_t available = bytes_.size() - offset_;
    if (element.count > available / instance_size) {
      uint64_t complete = available / instance_size;
      fail(file_, "the file ends in the middle of the data: the header declares " + std::to_string(element.count) +
                      " " + element.name + " elements of " + std::to_string(instance_size) +
                      " bytes, and the data ends after " + std::to_string(complete) + " of them (the file is truncated)" +
                      element_label(element, complete));
    }
    offset_ += element.count * instance_size;
  }

  void walk_instance(const PlyElement& element, uint64_t i) {
    for (const PlyProperty& property : element.properties) {
      if (!property.is_list) {
        take(size_of(property.type), element, i);
        continue;
      }
      int64_t count = read_integer(property.count_type, element, i);
      if (count < 0) fail(file_, "list '" + property.name + "' has a negative length" + element_label(element, i));
      bool collect = &property == roles_.face_indices;
      if (collect) corners_.clear();
      // Check the list fits before reading it item by item.
      if (static_cast<uint64_t>(count) > (bytes_.size() - offset_) / size_of(property.type)) fail_truncated(element, i);
      if (!collect) {
        take(static_cast<size_t>(count) * size_of(property.type), element, i);
        continue;
      }
      for (int64_t k = 0; k < count; ++k) corners_.push_back(read_integer(property.type, element, i));
      faces_.add(corners_, i, 0);
    }
  }

  int64_t read_integer(PlyType type, const PlyElement& element, uint64_t i) {
    const char* data = take(size_of(type), element, i);
    uint32_t raw = 0;
    unsigned char b[4] = {0, 0, 0, 0};
    std::memcpy(b, data, size_of(type));
    size_t n = size_of(type);
    bool big = header_.encoding == PlyEncoding::BinaryBigEndian;
    for (size_t k = 0; k < n; ++k) raw |= uint32_t{b[big ? n - 1 - k : k]} << (8 * k);
    switch (type) {
      case PlyType::Int8: return static_cast<int8_t>(raw);
      case PlyType::Int16: return static_cast<int16_t>(raw);
      case PlyType::Int32: return static_cast<int32_t>(raw);
      default: return raw;
    }
  }

  const char* take(size_t size, const PlyElement& element, uint64_t i) {
    if (bytes_.size() - offset_ < size) fail_truncated(element, i);
    const char* data = bytes_.data() + offset_;
    offset_ += size;
    return data;
  }

  [[noreturn]] void fail_truncated(const PlyElement& element, uint64_t i) {
    fail(file_, "the file ends in the middle of the data: the header declares " + std::to_string(element.count) +
                    " " + element.name + " elements (the file is truncated)" + element_label(element, i));
  }

  std::string_view bytes_;
  size_t offset_;
  const PlyHeader& header_;
  const Roles& roles_;
  const std::string& file_;
  FaceCollector faces_;
  std::vector<int64_t> corners_;
};

}  // namespace

// ---- ASCII ----------------------------------------------------------------------------

namespace {

// One element instance per line, values separated by blanks: the layout assimp reads.
class AsciiWalk {
 public:
  AsciiWalk(std::string_view bytes, const PlyHeader& header, const Roles& roles, const std::string& file)
      : bytes_(bytes), header_(header), roles_(roles), file_(file), faces_(roles.vertex->count, file),
        line_number_(header.body_line - 1), offset_(header.body_offset) {}

  PolygonMesh walk() {
    size_t at = find_binary_byte(bytes_.substr(offset_));
    if (at != std::string_view::npos)
      fail(file_, "the ASCII PLY data contains a control byte at offset " + std::to_string(offset_ + at));
    for (const PlyElement& element : header_.elements) {
      for (uint64_t i = 0; i < element.count; ++i) walk_instance(element, i);
    }
    return faces_.take();
  }

 private:
  void walk_instance(const PlyElement& element, uint64_t i) {
    std::string_view line;
    if (!next_line(line))
      fail(file_, "the file ends before all data: the header declares " + std::to_string(element.count) + " " +
                      element.name + " elements (the file is truncated)" + element_label(element, i));
    TokenReader tokens(line);
    if (trim_blanks(line).empty())
      fail(file_, "blank line where " + element.name + " data was expected" + element_label(element, i), line_number_);
    for (const PlyProperty& property : element.properties) walk_property(property, tokens, element, i);
    if (!tokens.rest().empty())
      fail(file_, "more values on the line than the header declares for a " + element.name +
                      element_label(element, i), line_number_);
  }

  void walk_property(const PlyProperty& property, TokenReader& tokens, const PlyElement& element, uint64_t i) {
    if (!property.is_list) {
      read_value(property.type, property, tokens, element, i);
      return;
    }
    auto count = static_cast<int64_t>(read_value(property.count_type, property, tokens, element, i));
    if (count < 0)
      fail(file_, "list '" + property.name + "' has a negative length" + element_label(element, i), line_number_);
    bool collect = &property == roles_.face_indices;
    if (collect) corners_.clear();
    for (int64_t k = 0; k < count; ++k) {
      double value = read_value(property.type, property, tokens, element, i);
      if (collect) corners_.push_back(static_cast<int64_t>(value));
    }
    if (collect) faces_.add(corners_, i, line_number_);
  }

  // The value, checked against its type; integers are exact in a double.
  double read_value(PlyType type, const PlyProperty& property, TokenReader& tokens, const PlyElement& element,
                    uint64_t i) {
    std::string_view token;
    if (!tokens.next(token))
      fail(file_, "too few values on the line: '" + property.name + "' is missing" + element_label(element, i),
           line_number_);
    if (!is_integer(type)) {
      double value = 0.0;
      if (!parse_real(token, value))
        fail(file_, "value " + quote_token(token) + " of '" + property.name + "' is not a number" +
                        element_label(element, i), line_number_);
      return value;
    }
    int64_t value = 0;
    if (!parse_integer(token, value) || value < integer_limit_low(type) || value > integer_limit_high(type))
      fail(file_, "value " + quote_token(token) + " of '" + property.name + "' is not a " + name_of(type) +
                      element_label(element, i), line_number_);
    return static_cast<double>(value);
  }

  // Lines end in "\n" or "\r\n".
  bool next_line(std::string_view& line) {
    if (offset_ >= bytes_.size()) return false;
    size_t end = bytes_.find('\n', offset_);
    if (end == std::string_view::npos) end = bytes_.size();
    line = bytes_.substr(offset_, end - offset_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find('\r') != std::string_view::npos)
      fail(file_, "a line ends in a lone carriage return; PLY lines end in LF or CR LF", line_number_ + 1);
    offset_ = end + 1;
    ++line_number_;
    return true;
  }

  std::string_view bytes_;
  const PlyHeader& header_;
  const Roles& roles_;
  const std::string& file_;
  FaceCollector faces_;
  std::vector<int64_t> corners_;
  int line_number_;
  size_t offset_;
};

}  // namespace

PlyContents check_ply(std::string_view bytes, const std::string& file) {
  PlyHeader header = parse_ply_header(bytes, file);
  Roles roles = find_roles(header, file);
  PlyContents contents;
  contents.encoding = header.encoding;
  contents.vertex_count = roles.vertex->count;
  contents.faces = header.encoding == PlyEncoding::Ascii ? AsciiWalk(bytes, header, roles, file).walk()
                                                         : BinaryWalk(bytes, header, roles, file).walk();
  contents.faces.format = std::string("PLY ") + name_of(header.encoding);
  return contents;
}

}  // namespace convray::mesh
