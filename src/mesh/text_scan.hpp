#pragma once
// Small, strict text-scanning helpers shared by the OBJ, OFF and ASCII PLY checks.
// Numbers are parsed with std::from_chars: exact (correctly rounded) and locale-free; only
// integers of up to 18 digits, which cannot overflow, are summed here directly (faster, and
// the same value: tests/mesh/text_scan_test.cpp checks them against strtoll).
// Internal to src/mesh.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace convray::mesh {

inline bool is_blank(char c) { return c == ' ' || c == '\t'; }
inline bool is_line_end(char c) { return c == '\n' || c == '\r'; }

// Walks text line by line. "\n", "\r\n" and a lone "\r" each end a line (as tinyobjloader
// splits them); the last line needs no terminator.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  // The next line without its terminator; false at the end of the text.
  bool next(std::string_view& line);
  int line_number() const { return line_number_; }  // 1-based number of the last line read
  size_t offset() const { return offset_; }         // where the next line starts

 private:
  std::string_view text_;
  size_t offset_ = 0;
  int line_number_ = 0;
};

// Walks the blank-separated tokens of one line.
class TokenReader {
 public:
  explicit TokenReader(std::string_view line) : line_(line) {}

  // Inline: the ASCII PLY body calls it once per value.
  bool next(std::string_view& token) {
    while (offset_ < line_.size() && is_blank(line_[offset_])) ++offset_;
    if (offset_ >= line_.size()) return false;
    size_t end = offset_;
    while (end < line_.size() && !is_blank(line_[end])) ++end;
    token = line_.substr(offset_, end - offset_);
    offset_ = end;
    return true;
  }
  // Everything after the tokens read so far, without leading blanks.
  std::string_view rest();

 private:
  std::string_view line_;
  size_t offset_ = 0;
};

// `line` without blanks at either end.
std::string_view trim_blanks(std::string_view line);

// A real number: from_chars syntax plus an optional leading '+', without "nan(payload)";
// "nan" and "inf" parse (the caller decides whether they are allowed). The whole token must
// be the number. Everything this accepts, assimp's fast_atoreal_move reads without throwing.
bool parse_real(std::string_view token, double& value);

// The run of decimal digits that starts at `at` and ends before `end` or the first other
// byte, if it has 1 to 18 digits (which cannot overflow 64 bits): its value, summed directly
// (a quarter of what std::from_chars spends on such a number, such as the indices of a large
// mesh), and the byte after it. nullptr for no digit or more than 18.
inline const char* scan_short_digits(const char* at, const char* end, uint64_t& value) {
  const char* const first = at;
  uint64_t sum = 0;
  for (; at != end; ++at) {
    const unsigned digit = static_cast<unsigned char>(*at) - unsigned{'0'};
    if (digit > 9) break;
    sum = sum * 10 + digit;
  }
  if (at == first || at - first > 18) return nullptr;
  value = sum;
  return at;
}

// A token of 1 to 18 decimal digits and nothing else (scan_short_digits); false otherwise.
inline bool parse_short_digits(std::string_view token, uint64_t& value) {
  const char* end = token.data() + token.size();
  return scan_short_digits(token.data(), end, value) == end && !token.empty();
}

// parse_integer for every token but the plain short ones.
bool parse_any_integer(std::string_view token, int64_t& value);

// A decimal integer with an optional sign; the whole token must be the number. Inline for
// plain digits, the common case.
inline bool parse_integer(std::string_view token, int64_t& value) {
  uint64_t magnitude = 0;
  if (!parse_short_digits(token, magnitude)) return parse_any_integer(token, value);
  value = static_cast<int64_t>(magnitude);
  return true;
}

// Only digits (no sign), as assimp's strtoul10 reads counts and indices.
bool parse_digits(std::string_view token, uint64_t& value);

// The token as it may appear in a message: at most 40 characters, control bytes escaped.
std::string quote_token(std::string_view token);

// Offset of the first byte that has no place in a text file (NUL and control bytes other
// than tab, line feed and carriage return), or std::string_view::npos.
size_t find_binary_byte(std::string_view text);

}  // namespace convray::mesh
