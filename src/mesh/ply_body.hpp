#pragma once
// The values of a PLY body, one after the other, in the types the header declares: the two
// ways they are stored (text; binary in either byte order) behind one interface, so that the
// element walk in ply_reader.cpp is written once. Internal to src/mesh.
//
// Both read strictly what the header declares: a binary body that ends early, a text value
// that is not a number of its type, a text line with too few values is an InputError naming
// the file, the line (text), the element and the property. What follows the declared values
// (on a text line, or after the last element) is not read.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/ply_header.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {

// " (vertex 3)", " (face 0)", " (camera 0)": an element instance in messages.
std::string element_label(const PlyElement& element, uint64_t index);

// ---- Binary ---------------------------------------------------------------------------

template <bool kBigEndian>
class BinaryPlyBody {
 public:
  static constexpr bool kBinary = true;

  BinaryPlyBody(std::string_view bytes, size_t offset, const std::string& file)
      : bytes_(bytes), offset_(offset), file_(file) {}

  // Element instances need no framing in binary.
  void begin(const PlyElement& element, uint64_t index) { element_ = &element, index_ = index; }
  void end() {}

  double real(PlyType type, const PlyProperty&) {
    switch (type) {
      case PlyType::Float32: return std::bit_cast<float>(load<uint32_t>());
      case PlyType::Float64: return std::bit_cast<double>(load<uint64_t>());
      default: return static_cast<double>(integer_of(type));
    }
  }
  // Only for the integer types (the plan in ply_reader.cpp sees to it).
  int64_t integer(PlyType type, const PlyProperty&) { return integer_of(type); }
  void skip(PlyType type, uint64_t count, const PlyProperty&) {
    if (count > (bytes_.size() - offset_) / size_of(type)) fail_truncated();
    offset_ += static_cast<size_t>(count) * size_of(type);
  }

  size_t remaining() const { return bytes_.size() - offset_; }
  int line() const { return 0; }

  // Skips `count` instances of `size` bytes each, after checking they are all there.
  void skip_fixed(const PlyElement& element, uint64_t size);
  [[noreturn]] void fail_truncated() const;

 private:
  template <typename Bits>
  Bits load() {
    if (bytes_.size() - offset_ < sizeof(Bits)) fail_truncated();
    Bits bits;
    std::memcpy(&bits, bytes_.data() + offset_, sizeof(Bits));
    offset_ += sizeof(Bits);
    if constexpr (kBigEndian != (std::endian::native == std::endian::big)) bits = swapped(bits);
    return bits;
  }

  template <typename Bits>
  static Bits swapped(Bits bits) {
    if constexpr (sizeof(Bits) == 1) return bits;
    else if constexpr (sizeof(Bits) == 2) return __builtin_bswap16(bits);
    else if constexpr (sizeof(Bits) == 4) return __builtin_bswap32(bits);
    else return __builtin_bswap64(bits);
  }

  int64_t integer_of(PlyType type) {
    switch (type) {
      case PlyType::Int8: return static_cast<int8_t>(load<uint8_t>());
      case PlyType::UInt8: return load<uint8_t>();
      case PlyType::Int16: return static_cast<int16_t>(load<uint16_t>());
      case PlyType::UInt16: return load<uint16_t>();
      case PlyType::Int32: return static_cast<int32_t>(load<uint32_t>());
      case PlyType::UInt32: return load<uint32_t>();
      case PlyType::Float32: return static_cast<int64_t>(std::bit_cast<float>(load<uint32_t>()));
      case PlyType::Float64: return static_cast<int64_t>(std::bit_cast<double>(load<uint64_t>()));
    }
    return 0;
  }

  std::string_view bytes_;
  size_t offset_;
  const std::string& file_;
  const PlyElement* element_ = nullptr;
  uint64_t index_ = 0;
};

// ---- Text -----------------------------------------------------------------------------

// One element instance per line, values separated by blanks. Blank lines carry no values
// and are skipped; values after the declared ones are ignored.
//
// The per-value calls are inline, each with its common case first (a large mesh has
// millions of values); what is unusual or wrong goes to the functions in ply_body.cpp,
// which decide it as if nothing had been tried before.
class AsciiPlyBody {
 public:
  static constexpr bool kBinary = false;

  AsciiPlyBody(std::string_view bytes, size_t offset, int first_line, const std::string& file);

  void begin(const PlyElement& element, uint64_t index);
  void end();

  double real(PlyType type, const PlyProperty& property) {
    if (is_integer(type)) return static_cast<double>(integer(type, property));
    std::string_view text = token(property);
    double value = 0.0;
    if (!parse_real(text, value)) fail_not_a_number(text, property);
    // A float is a float32, in text as in binary.
    return type == PlyType::Float32 ? static_cast<double>(static_cast<float>(value)) : value;
  }

  int64_t integer(PlyType type, const PlyProperty& property) {
    std::string_view text = token(property);
    int64_t value = 0;
    if (parse_integer(text, value) && value >= lowest(type) && value <= highest(type)) return value;
    return unusual_integer(text, type, property);
  }

  void skip(PlyType type, uint64_t count, const PlyProperty& property);

  // A shortcut through the commonest line of a large text mesh: an instance that is one list
  // of integers ("3 17 4 9", a face), written plainly (unsigned digits, blanks between them,
  // within their types). Reads the list into `items` and the line as begin and end would;
  // or, for anything else, returns false having read nothing, and begin, integer, ... read
  // the line the general way, and report what is wrong with it. A line that starts with a
  // blank always goes the general way (the tests compare the two ways with it).
  bool read_plain_list(const PlyElement& element, uint64_t index, const PlyProperty& list,
                       std::vector<int64_t>& items);

  size_t remaining() const { return bytes_.size() - offset_; }
  int line() const { return line_number_; }

 private:
  static int64_t lowest(PlyType type) {
    switch (type) {
      case PlyType::Int8: return INT8_MIN;
      case PlyType::Int16: return INT16_MIN;
      case PlyType::Int32: return INT32_MIN;
      default: return 0;
    }
  }
  static int64_t highest(PlyType type) {
    switch (type) {
      case PlyType::Int8: return INT8_MAX;
      case PlyType::UInt8: return UINT8_MAX;
      case PlyType::Int16: return INT16_MAX;
      case PlyType::UInt16: return UINT16_MAX;
      case PlyType::Int32: return INT32_MAX;
      default: return UINT32_MAX;
    }
  }

  std::string_view token(const PlyProperty& property) {
    std::string_view text;
    if (!tokens_.next(text)) fail_missing(property);
    return text;
  }

  int64_t unusual_integer(std::string_view text, PlyType type, const PlyProperty& property);
  void find_suspect();
  bool next_line(std::string_view& line);
  void check_line(std::string_view line);
  [[noreturn]] void fail_missing(const PlyProperty& property) const;
  [[noreturn]] void fail_not_a_number(std::string_view text, const PlyProperty& property) const;
  [[noreturn]] void fail_here(const std::string& what) const;

  std::string_view bytes_;
  size_t offset_;
  int line_number_;
  const std::string& file_;
  // The first byte not yet looked at that could fail check_line; lines before it need no
  // check (see next_line).
  size_t suspect_;
  TokenReader tokens_{std::string_view()};
  const PlyElement* element_ = nullptr;
  uint64_t index_ = 0;
};

}  // namespace convray::mesh
