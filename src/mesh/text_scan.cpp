#include "mesh/text_scan.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace convray::mesh {
bool LineReader::next(std::string_view& line) {
  if (offset_ >= text_.size()) return false;
  size_t end = offset_;
  while (end < text_.size() && !is_line_end(text_[end])) ++end;
  line = text_.substr(offset_, end - offset_);
  if (end < text_.size() && text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n')
    ++end;
  offset_ = std::min(end + 1, text_.size());  // a last line without a line end ends the text
  ++line_number_;
  return true;
}

std::string_view TokenReader::rest() {
  while (offset_ < line_.size() && is_blank(line_[offset_])) ++offset_;
  return line_.substr(offset_);
}

std::string_view trim_blanks(std::string_view line) {
  size_t begin = 0;
  while (begin < line.size() && is_blank(line[begin])) ++begin;
  size_t end = line.size();
  while (end > begin && is_blank(line[end - 1])) --end;
  return line.substr(begin, end - begin);
}

bool parse_real(std::string_view token, double& value) {
  // from_chars rejects a leading '+', which every writer of these formats may emit. One sign
  // only: "+-.5" is no number (assimp gave up halfway through it and leaked; fuzz-found), and
  // from_chars already refuses "--1" and "-+1".
  const bool had_plus = !token.empty() && token.front() == '+';
  if (had_plus) token.remove_prefix(1);
  if (had_plus && !token.empty() && (token.front() == '+' || token.front() == '-')) return false;
  // "nan(payload)" is from_chars syntax that assimp's parser stops halfway through.
  if (token.empty() || token.find('(') != std::string_view::npos) return false;
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, value, std::chars_format::general);
  // Literals beyond double's range ("1e999", "1e-999") are numbers all the same: strtod
  // rounds them to infinity or zero, and the caller's finiteness check reports the former.
  if (ec == std::errc::result_out_of_range && ptr == end) {
    value = std::strtod(std::string(token).c_str(), nullptr);
    return true;
  }
  return ec == std::errc() && ptr == end;
}

bool parse_any_integer(std::string_view token, int64_t& value) {
  const bool had_plus = !token.empty() && token.front() == '+';
  if (had_plus) token.remove_prefix(1);
  if (token.empty() || token.front() == '+' || (had_plus && token.front() == '-')) return false;
  const char* end = token.data() + token.size();
  const bool negative = token.front() == '-';
  uint64_t magnitude = 0;
  if (parse_short_digits(token.substr(negative ? 1 : 0), magnitude)) {
    const auto signed_magnitude = static_cast<int64_t>(magnitude);
    value = negative ? -signed_magnitude : signed_magnitude;
    return true;
  }
  auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}

bool parse_digits(std::string_view token, uint64_t& value) {
  if (token.empty() || token.front() < '0' || token.front() > '9') return false;
  if (parse_short_digits(token, value)) return true;
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}

std::string quote_token(std::string_view token) {
  constexpr size_t kMaxShown = 40;
  std::string shown = "'";
  for (size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    unsigned char c = static_cast<unsigned char>(token[i]);
    if (c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      shown += escaped;
    } else {
      shown += static_cast<char>(c);
    }
  }
  if (token.size() > kMaxShown) shown += "...";
  return shown + "'";
}

size_t find_binary_byte(std::string_view text) {
  // Bitwise, not short-circuit, so that the block loop below has no branch per byte.
  const auto is_binary = [](char byte) -> unsigned {
    const auto c = static_cast<unsigned char>(byte);
    return unsigned{c < 0x20} & unsigned{c != '\t'} & unsigned{c != '\n'} & unsigned{c != '\r'};
  };
  // Whole blocks first, which the compiler vectorises: text is clean nearly always, and a
  // large mesh has megabytes of it (byte by byte it was a tenth of reading an ASCII PLY).
  constexpr size_t kBlock = 64;
  size_t i = 0;
  for (; i + kBlock <= text.size(); i += kBlock) {
    unsigned any = 0;
    for (size_t k = 0; k < kBlock; ++k) any |= is_binary(text[i + k]);
    if (any) break;
  }
  for (; i < text.size(); ++i) {
    if (is_binary(text[i])) return i;
  }
  return std::string_view::npos;
}

}  // namespace convray::mesh
