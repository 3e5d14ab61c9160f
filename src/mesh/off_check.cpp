#include "mesh/off_check.hpp"

#include <cmath>
#include <cstdint>

#include "mesh/load_error.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

// Faces of more corners are dropped by assimp without a word.
constexpr uint64_t kMaxOffCorners = 9;

// The optional prefixes of the OFF keyword say what else each vertex line carries.
struct OffLayout {
  bool texture = false;      // ST: two texture coordinates
  bool colour = false;       // C: one to four colour values
  bool normal = false;       // N: three normal components
  bool homogeneous = false;  // 4: a fourth coordinate w

  size_t numbers_per_vertex() const { return 3 + (homogeneous ? 1 : 0) + (normal ? 3 : 0) + (colour ? 1 : 0) + (texture ? 2 : 0); }
};

class OffWalk {
 public:
  OffWalk(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  OffContents walk() {
    reject_binary_bytes();
    skip_to_token();
    layout_ = read_keyword();
    contents_.vertex_count = read_count("vertex");
    uint64_t face_count = read_count("face");
    read_count("edge");
    if (contents_.vertex_count == 0) fail(file_, "the OFF header declares no vertices");
    if (face_count == 0) fail(file_, "the OFF header declares no faces");
    for (uint64_t v = 0; v < contents_.vertex_count; ++v) read_vertex(v);
    for (uint64_t f = 0; f < face_count; ++f) read_face(f, face_count);
    contents_.faces.format = "OFF";
    return std::move(contents_);
  }

 private:
  void reject_binary_bytes() {
    size_t at = find_binary_byte(bytes_);
    if (at != std::string_view::npos)
      fail(file_, "the file contains a control byte at offset " + std::to_string(at) +
                      ", which has no place in an OFF (text) file; binary OFF is not supported");
  }

  // Blanks, line ends and '#' comments separate header tokens, as assimp's NextToken has it.
  void skip_to_token() {
    for (;;) {
      while (offset_ < bytes_.size() && (is_blank(bytes_[offset_]) || is_line_end(bytes_[offset_]))) advance();
      if (offset_ >= bytes_.size() || bytes_[offset_] != '#') return;
      while (offset_ < bytes_.size() && !is_line_end(bytes_[offset_])) ++offset_;
    }
  }

  void advance() {
    // Count "\n", "\r\n" and a lone "\r" as one line end each.
    if (bytes_[offset_] == '\n' || (bytes_[offset_] == '\r' && (offset_ + 1 >= bytes_.size() || bytes_[offset_ + 1] != '\n')))
      ++line_;
    ++offset_;
  }

  std::string_view header_token() {
    size_t end = offset_;
    while (end < bytes_.size() && !is_blank(bytes_[end]) && !is_line_end(bytes_[end])) ++end;
    std::string_view token = bytes_.substr(offset_, end - offset_);
    offset_ = end;
    skip_to_token();
    return token;
  }

  OffLayout read_keyword() {
    int line = line_;
    std::string_view keyword = header_token();
    OffLayout layout;
    std::string_view rest = keyword;
    auto take = [&rest](std::string_view prefix) {
      if (rest.substr(0, prefix.size()) != prefix) return false;
      rest.remove_prefix(prefix.size());
      return true;
    };
    layout.texture = take("ST");
    layout.colour = take("C");
    layout.normal = take("N");
    layout.homogeneous = take("4");
    if (!rest.empty() && rest.front() == 'n')
      fail(file_, "OFF files of other dimensions than 3 (nOFF) are not supported", line);
    if (rest != "OFF")
      fail(file_, "not an OFF file: it does not start with the keyword OFF (or COFF, NOFF, STOFF, 4OFF, ...)", line);
    return layout;
  }

  uint64_t read_count(const char* what) {
    int line = line_;
    if (offset_ >= bytes_.size())
      fail(file_, std::string("the OFF header ends before its ") + what + " count (the file is truncated)");
    std::string_view token = header_token();
    uint64_t count = 0;
    if (!parse_digits(token, count) || count > 0xffffffffu)
      fail(file_, std::string("the OFF ") + what + " count " + quote_token(token) + " is not a whole number below 2^32",
           line);
    return count;
  }

  // The rest of the current line; then past the line end and any blank lines after it, the
  // way assimp's GetNextLine moves on.
  bool next_line(std::string_view& line) {
    if (offset_ >= bytes_.size()) return false;
    size_t end = offset_;
    while (end < bytes_.size() && !is_line_end(bytes_[end])) ++end;
    line = bytes_.substr(offset_, end - offset_);
    line_number_of_last_ = line_;
    offset_ = end;
    while (offset_ < bytes_.size() && is_line_end(bytes_[offset_])) advance();
    if (line.size() > kMaxOffLineLength)
      fail(file_, "line longer than " + std::to_string(kMaxOffLineLength) + " characters", line_number_of_last_);
    return true;
  }

  void read_vertex(uint64_t v) {
    std::string_view line;
    if (!next_line(line))
      fail(file_, "the file ends after " + std::to_string(v) + " of the " + std::to_string(contents_.vertex_count) +
                      " vertices the header declares (the file is truncated)" + in_vertex(v));
    TokenReader tokens(line);
    for (size_t k = 0; k < layout_.numbers_per_vertex(); ++k) {
      std::string_view token;
      double value = 0.0;
      if (!tokens.next(token))
        fail(file_, "vertex line has " + std::to_string(k) + " numbers; " + std::to_string(layout_.numbers_per_vertex()) +
                        " are needed" + in_vertex(v), line_number_of_last_);
      if (!parse_real(token, value))
        fail(file_, "vertex value " + quote_token(token) + " is not a number" + in_vertex(v), line_number_of_last_);
      if (k < 3 && !std::isfinite(value))
        fail(file_, "vertex has a non-finite coordinate " + quote_token(token) + in_vertex(v), line_number_of_last_);
    }
  }

  void read_face(uint64_t f, uint64_t face_count) {
    std::string_view line;
    if (!next_line(line))
      fail(file_, "the file ends after " + std::to_string(f) + " of the " + std::to_string(face_count) +
                      " faces the header declares (the file is truncated)" + in_face(f));
    TokenReader tokens(line);
    std::string_view token;
    uint64_t corner_count = 0;
    if (!tokens.next(token) || !parse_digits(token, corner_count))
      fail(file_, "face line does not start with its number of corners" + in_face(f), line_number_of_last_);
    if (corner_count < 3)
      fail(file_, "face has " + std::to_string(corner_count) + " corners; at least 3 are needed" + in_face(f),
           line_number_of_last_);
    if (corner_count > kMaxOffCorners)
      fail(file_, "face has " + std::to_string(corner_count) + " corners; the OFF reader handles at most " +
                      std::to_string(kMaxOffCorners) + in_face(f), line_number_of_last_);
    corners_.clear();
    for (uint64_t k = 0; k < corner_count; ++k) corners_.push_back(read_index(tokens, f, corner_count));
    contents_.faces.add_face(corners_);
  }

  int64_t read_index(TokenReader& tokens, uint64_t f, uint64_t corner_count) {
    std::string_view token;
    if (!tokens.next(token))
      fail(file_, "face line has fewer indices than its " + std::to_string(corner_count) + " corners" + in_face(f),
           line_number_of_last_);
    // assimp reads indices as bare digits ("+1" would be 0 to it); a negative index is
    // reported as out of range, which is what it is.
    int64_t index = 0;
    uint64_t digits = 0;
    if (parse_digits(token, digits) && digits <= uint64_t{INT64_MAX}) index = static_cast<int64_t>(digits);
    else if (token.front() != '-' || !parse_integer(token, index))
      fail(file_, "face index " + quote_token(token) + " is not a whole number" + in_face(f), line_number_of_last_);
    if (index < 0 || static_cast<uint64_t>(index) >= contents_.vertex_count)
      fail(file_, "face refers to vertex " + std::to_string(index) + ", but the file has " +
                      std::to_string(contents_.vertex_count) + " vertices" + in_face(f), line_number_of_last_);
    return index;
  }

  std::string_view bytes_;
  const std::string& file_;
  size_t offset_ = 0;
  int line_ = 1;
  int line_number_of_last_ = 0;
  OffLayout layout_;
  OffContents contents_;
  std::vector<int64_t> corners_;
};

}  // namespace

OffContents check_off(std::string_view bytes, const std::string& file) { return OffWalk(bytes, file).walk(); }

}  // namespace convray::mesh
