#include "mesh/ply_body.hpp"

#include <cmath>
#include <limits>

#include "mesh/load_error.hpp"

namespace convray::mesh {
namespace {

int64_t lowest(PlyType type) {
  switch (type) {
    case PlyType::Int8: return std::numeric_limits<int8_t>::min();
    case PlyType::Int16: return std::numeric_limits<int16_t>::min();
    case PlyType::Int32: return std::numeric_limits<int32_t>::min();
    default: return 0;
  }
}

int64_t highest(PlyType type) {
  switch (type) {
    case PlyType::Int8: return std::numeric_limits<int8_t>::max();
    case PlyType::UInt8: return std::numeric_limits<uint8_t>::max();
    case PlyType::Int16: return std::numeric_limits<int16_t>::max();
    case PlyType::UInt16: return std::numeric_limits<uint16_t>::max();
    case PlyType::Int32: return std::numeric_limits<int32_t>::max();
    default: return std::numeric_limits<uint32_t>::max();
  }
}

}  // namespace

std::string element_label(const PlyElement& element, uint64_t index) {
  return " (" + element.name + " " + std::to_string(index) + ")";
}

// ---- Binary ---------------------------------------------------------------------------

template <bool kBigEndian>
void BinaryPlyBody<kBigEndian>::skip_fixed(const PlyElement& element, uint64_t size) {
  element_ = &element;
  if (size == 0) return;
  const uint64_t complete = remaining() / size;
  if (element.count > complete)
    fail(file_, "the file ends in the middle of the data: the header declares " + std::to_string(element.count) +
                    " " + element.name + " elements of " + std::to_string(size) + " bytes, and the data ends after " +
                    std::to_string(complete) + " of them (the file is truncated)" + element_label(element, complete));
  offset_ += static_cast<size_t>(element.count * size);
}

template <bool kBigEndian>
void BinaryPlyBody<kBigEndian>::fail_truncated() const {
  fail(file_, "the file ends in the middle of the data: the header declares " + std::to_string(element_->count) +
                  " " + element_->name + " elements (the file is truncated)" + element_label(*element_, index_));
}

template class BinaryPlyBody<false>;
template class BinaryPlyBody<true>;

// ---- Text -----------------------------------------------------------------------------

void AsciiPlyBody::begin(const PlyElement& element, uint64_t index) {
  element_ = &element, index_ = index;
  std::string_view line;
  do {
    if (!next_line(line))
      fail(file_, "the file ends before all data: the header declares " + std::to_string(element.count) + " " +
                      element.name + " elements (the file is truncated)" + element_label(element, index));
  } while (trim_blanks(line).empty());
  tokens_ = TokenReader(line);
}

// Values after those the header declares are ignored, as line-based readers ignore them
// (VCG's writers leave some after faces' texture coordinates).
void AsciiPlyBody::end() {}

double AsciiPlyBody::real(PlyType type, const PlyProperty& property) {
  if (is_integer(type)) return static_cast<double>(integer(type, property));
  std::string_view text = token(property);
  double value = 0.0;
  if (!parse_real(text, value))
    fail_here("value " + quote_token(text) + " of '" + property.name + "' is not a number" +
              element_label(*element_, index_));
  // A float is a float32, in text as in binary.
  return type == PlyType::Float32 ? static_cast<double>(static_cast<float>(value)) : value;
}

// A whole number written as a real ("3.0", "1e2") is that integer: some writers print every
// value with a decimal point.
static bool parse_whole_number(std::string_view text, int64_t& value) {
  if (parse_integer(text, value)) return true;
  double real = 0.0;
  if (!parse_real(text, real) || !(std::abs(real) <= 9.0e15) || real != std::floor(real)) return false;
  value = static_cast<int64_t>(real);
  return true;
}

int64_t AsciiPlyBody::integer(PlyType type, const PlyProperty& property) {
  std::string_view text = token(property);
  int64_t value = 0;
  if (!parse_whole_number(text, value) || value < lowest(type) || value > highest(type))
    fail_here("value " + quote_token(text) + " of '" + property.name + "' is not " +
              (name_of(type)[0] == 'i' ? "an " : "a ") + name_of(type) +
              element_label(*element_, index_));
  return value;
}

// Values nobody reads need only be numbers.
void AsciiPlyBody::skip(PlyType, uint64_t count, const PlyProperty& property) {
  for (uint64_t k = 0; k < count; ++k) {
    std::string_view text = token(property);
    double value = 0.0;
    if (!parse_real(text, value))
      fail_here("value " + quote_token(text) + " of '" + property.name + "' is not a number" +
                element_label(*element_, index_));
  }
}

// Lines end in "\n" or "\r\n".
bool AsciiPlyBody::next_line(std::string_view& line) {
  if (offset_ >= bytes_.size()) return false;
  size_t end = bytes_.find('\n', offset_);
  if (end == std::string_view::npos) end = bytes_.size();
  line = bytes_.substr(offset_, end - offset_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  ++line_number_;
  offset_ = end + 1;
  size_t at = find_binary_byte(line);
  if (line.find('\r') != std::string_view::npos)
    fail_here("a line ends in a lone carriage return; PLY lines end in LF or CR LF");
  if (at != std::string_view::npos)
    fail_here("the ASCII PLY data contains the control byte " + quote_token(line.substr(at, 1)));
  return true;
}

std::string_view AsciiPlyBody::token(const PlyProperty& property) {
  std::string_view text;
  if (!tokens_.next(text))
    fail_here("too few values on the line: '" + property.name + "' is missing (the header does not match the "
              "data)" + element_label(*element_, index_));
  return text;
}

void AsciiPlyBody::fail_here(const std::string& what) const { fail(file_, what, line_number_); }

}  // namespace convray::mesh
