#include "mesh/ply_body.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/load_error.hpp"

namespace convray::mesh {
namespace {

// The first byte at or after `from` that could make a line fail AsciiPlyBody::check_line: a
// control byte, or a carriage return that is not the CR of a CR LF; bytes.size() if none.
size_t next_suspect(std::string_view bytes, size_t from) {
  if (from >= bytes.size()) return bytes.size();
  const size_t binary = find_binary_byte(bytes.substr(from));
  size_t lone_return = bytes.find('\r', from);
  while (lone_return != std::string_view::npos && lone_return + 1 < bytes.size() && bytes[lone_return + 1] == '\n')
    lone_return = bytes.find('\r', lone_return + 2);
  return std::min({binary == std::string_view::npos ? bytes.size() : from + binary, lone_return, bytes.size()});
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

AsciiPlyBody::AsciiPlyBody(std::string_view bytes, size_t offset, int first_line, const std::string& file)
    : bytes_(bytes), offset_(offset), line_number_(first_line - 1), file_(file),
      suspect_(next_suspect(bytes, offset)) {}

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

// A whole number written as a real ("3.0", "1e2") is that integer: some writers print every
// value with a decimal point.
static bool parse_whole_number(std::string_view text, int64_t& value) {
  if (parse_integer(text, value)) return true;
  double real = 0.0;
  if (!parse_real(text, real) || !(std::abs(real) <= 9.0e15) || real != std::floor(real)) return false;
  value = static_cast<int64_t>(real);
  return true;
}

// A token that is no plain integer of its type: a whole number written as a real, or an error.
int64_t AsciiPlyBody::unusual_integer(std::string_view text, PlyType type, const PlyProperty& property) {
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
    if (!parse_real(text, value)) fail_not_a_number(text, property);
  }
}

namespace {

// Plain unsigned digits (at most 18) at `at`, followed by a blank, a line end or the end of
// the body: their value, and `at` moved past them.
bool plain_integer(const char*& at, const char* end, uint64_t& value) {
  const char* after = scan_short_digits(at, end, value);
  if (!after || (after != end && !is_blank(*after) && !is_line_end(*after))) return false;
  at = after;
  return true;
}

}  // namespace

bool AsciiPlyBody::read_plain_list(const PlyElement& element, uint64_t index, const PlyProperty& list,
                                   std::vector<int64_t>& items) {
  // After a last line without a line end, offset_ is one past the end (see next_line).
  if (offset_ >= bytes_.size()) return false;
  const char* at = bytes_.data() + offset_;
  const char* const end = bytes_.data() + bytes_.size();
  uint64_t count = 0, item = 0;
  if (!plain_integer(at, end, count) || static_cast<int64_t>(count) > highest(list.count_type)) return false;
  const auto item_max = static_cast<uint64_t>(highest(list.type));
  items.clear();
  for (uint64_t k = 0; k < count; ++k) {
    if (at == end || !is_blank(*at)) return false;
    while (at != end && is_blank(*at)) ++at;
    if (!plain_integer(at, end, item) || item > item_max) return false;
    items.push_back(static_cast<int64_t>(item));
  }
  // What follows the list is ignored, as end() ignores it; the line must only pass check_line.
  find_suspect();
  const size_t line_end = std::min(bytes_.find('\n', static_cast<size_t>(at - bytes_.data())), bytes_.size());
  if (suspect_ < line_end) return false;
  element_ = &element, index_ = index;
  ++line_number_;
  offset_ = line_end + 1;
  tokens_ = TokenReader(std::string_view());
  return true;
}

// After a line with a suspect byte that passed check_line, the search goes on after it.
void AsciiPlyBody::find_suspect() {
  if (offset_ > suspect_) suspect_ = next_suspect(bytes_, offset_);
}

// Lines end in "\n" or "\r\n". Only a line with a suspect byte in it (none, in nearly every
// file) is looked at byte by byte; the search for the next one spans many lines at a time.
bool AsciiPlyBody::next_line(std::string_view& line) {
  if (offset_ >= bytes_.size()) return false;
  find_suspect();
  size_t end = bytes_.find('\n', offset_);
  if (end == std::string_view::npos) end = bytes_.size();
  line = bytes_.substr(offset_, end - offset_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  ++line_number_;
  offset_ = end + 1;
  if (suspect_ < end) check_line(line);
  return true;
}

void AsciiPlyBody::check_line(std::string_view line) {
  size_t at = find_binary_byte(line);
  if (line.find('\r') != std::string_view::npos)
    fail_here("a line ends in a lone carriage return; PLY lines end in LF or CR LF");
  if (at != std::string_view::npos)
    fail_here("the ASCII PLY data contains the control byte " + quote_token(line.substr(at, 1)));
}

void AsciiPlyBody::fail_missing(const PlyProperty& property) const {
  fail_here("too few values on the line: '" + property.name + "' is missing (the header does not match the "
            "data)" + element_label(*element_, index_));
}

void AsciiPlyBody::fail_not_a_number(std::string_view text, const PlyProperty& property) const {
  fail_here("value " + quote_token(text) + " of '" + property.name + "' is not a number" +
            element_label(*element_, index_));
}

void AsciiPlyBody::fail_here(const std::string& what) const { fail(file_, what, line_number_); }

}  // namespace convray::mesh
