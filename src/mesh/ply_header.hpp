#pragma once
// The header of a PLY file. The lines that define the body's layout (format, element,
// property, end_header) must each be in their one correct form; every other line (comment,
// obj_info, blank lines, other writers' additions) is skipped. Internal to src/mesh.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace convray::mesh {

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };
enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;        // of the value, or of each list item
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;   // lists only: the type of the leading item count
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;

  const PlyProperty* find(std::string_view property_name) const;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  size_t body_offset = 0;  // first byte after the end_header line
  int body_line = 1;       // 1-based line number of the first body line (ASCII)

  const PlyElement* find(std::string_view element_name) const;
};

// Throws InputError, with the line, for anything but a well-formed header.
PlyHeader parse_ply_header(std::string_view bytes, const std::string& file);

size_t size_of(PlyType type);
bool is_integer(PlyType type);
const char* name_of(PlyType type);
const char* name_of(PlyEncoding encoding);  // "ascii", "binary little-endian", ...

}  // namespace convray::mesh
