#include "mesh/stl_check.hpp"

#include "mesh/load_error.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

constexpr uint64_t kBinaryHeaderSize = 84;  // 80 bytes of anything, then a uint32 count
constexpr uint64_t kBinaryTriangleSize = 50;

uint32_t binary_triangle_count(std::string_view bytes) {
  const auto* count = reinterpret_cast<const unsigned char*>(bytes.data() + 80);
  return uint32_t{count[0]} | uint32_t{count[1]} << 8 | uint32_t{count[2]} << 16 | uint32_t{count[3]} << 24;
}

bool starts_with_solid(std::string_view bytes) {
  size_t start = 0;
  while (start < bytes.size() && (is_blank(bytes[start]) || is_line_end(bytes[start]))) ++start;
  return bytes.substr(start, 5) == "solid";
}

// The last token of the file must be `endsolid` or follow it on the last line
// (`endsolid name`).
bool ends_with_endsolid(std::string_view bytes) {
  size_t end = bytes.size();
  while (end > 0 && (is_blank(bytes[end - 1]) || is_line_end(bytes[end - 1]))) --end;
  size_t line_start = bytes.find_last_of("\r\n", end == 0 ? 0 : end - 1);
  line_start = line_start == std::string_view::npos ? 0 : line_start + 1;
  std::string_view last_line = trim_blanks(bytes.substr(line_start, end - line_start));
  return last_line.substr(0, 8) == "endsolid";
}

void check_ascii(std::string_view bytes, const std::string& file) {
  size_t at = find_binary_byte(bytes);
  if (at != std::string_view::npos)
    fail(file, "the ASCII STL contains a control byte at offset " + std::to_string(at));
  if (!ends_with_endsolid(bytes))
    fail(file, "the ASCII STL does not end with an 'endsolid' line (the file is truncated)");
}

}  // namespace

StlContents check_stl(std::string_view bytes, const std::string& file) {
  StlContents contents;
  uint64_t size = bytes.size();
  if (size >= kBinaryHeaderSize) {
    contents.triangle_count = binary_triangle_count(bytes);
    if (kBinaryHeaderSize + kBinaryTriangleSize * contents.triangle_count == size) return contents;
  }
  if (starts_with_solid(bytes) && bytes.find('\0') == std::string_view::npos) {
    check_ascii(bytes, file);
    return {StlEncoding::Ascii, 0};
  }
  if (size < kBinaryHeaderSize)
    fail(file, "not an STL file: too short for a binary STL (" + std::to_string(size) +
                   " bytes, the header alone is 84) and not ASCII STL (it does not start with 'solid')");
  uint64_t expected = kBinaryHeaderSize + kBinaryTriangleSize * contents.triangle_count;
  fail(file, "binary STL of the wrong size: the header declares " + std::to_string(contents.triangle_count) +
                 " triangles, which take 84 + 50 x " + std::to_string(contents.triangle_count) + " = " +
                 std::to_string(expected) + " bytes, but the file has " + std::to_string(size) + " bytes" +
                 (size < expected ? " (the file is truncated)" : ""));
}

}  // namespace convray::mesh
