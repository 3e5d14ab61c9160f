#include "mesh/ply_header.hpp"

#include <algorithm>
#include <optional>

#include "mesh/load_error.hpp"
#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

// The soup indexes vertices with uint32_t; no element of a file we can read has more.
constexpr uint64_t kMaxElementCount = 0xffffffffu;

std::optional<PlyType> parse_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::Int8;
  if (name == "uchar" || name == "uint8") return PlyType::UInt8;
  if (name == "short" || name == "int16") return PlyType::Int16;
  if (name == "ushort" || name == "uint16") return PlyType::UInt16;
  if (name == "int" || name == "int32") return PlyType::Int32;
  if (name == "uint" || name == "uint32") return PlyType::UInt32;
  if (name == "float" || name == "float32") return PlyType::Float32;
  if (name == "double" || name == "float64") return PlyType::Float64;
  return std::nullopt;
}

// Header lines end in "\n" or "\r\n". The body starts right after the end_header line's "\n",
// whatever its first byte is (a binary body may well start with 0x0a or 0x0d 0x0a).
class HeaderLines {
 public:
  HeaderLines(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  bool next(std::string_view& line) {
    if (offset_ >= bytes_.size()) return false;
    size_t end = bytes_.find('\n', offset_);
    if (end == std::string_view::npos) end = bytes_.size();
    line = bytes_.substr(offset_, end - offset_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++line_number_;
    offset_ = std::min(end + 1, bytes_.size());  // a last line without '\n' ends the bytes
    check_text(line);
    return true;
  }
  int line_number() const { return line_number_; }
  size_t offset() const { return offset_; }

 private:
  void check_text(std::string_view line) const {
    for (char c : line) {
      unsigned char byte = static_cast<unsigned char>(c);
      if ((byte < 0x20 && c != '\t') || byte == 0x7f)
        fail(file_, "the PLY header contains a control byte (or a line ending in a lone carriage return)",
             line_number_);
    }
  }

  std::string_view bytes_;
  const std::string& file_;
  size_t offset_ = 0;
  int line_number_ = 0;
};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  TokenReader reader(line);
  std::string_view token;
  while (reader.next(token)) tokens.push_back(token);
  return tokens;
}

class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& file) : bytes_(bytes), lines_(bytes, file), file_(file) {}

  PlyHeader parse() {
    std::string_view line;
    if (bytes_.substr(0, 3) != "ply" || !lines_.next(line) || trim_blanks(line) != "ply")
      fail(file_, "not a PLY file: it does not start with the line 'ply'");
    while (lines_.next(line)) {
      std::vector<std::string_view> tokens = split(line);
      // Blank lines, comments, obj_info and the other lines writers add (with a keyword of
      // their own or none) carry nothing the body's layout depends on.
      if (tokens.empty()) continue;
      if (tokens[0] == "format") read_format(tokens);
      else if (tokens[0] == "element") read_element(tokens);
      else if (tokens[0] == "property") read_property(tokens);
      else if (tokens[0] == "end_header") return finish();
    }
    fail(file_, "the PLY header has no end_header line (the file may be truncated)");
  }

 private:
  [[noreturn]] void fail_here(const std::string& what) { fail(file_, what, lines_.line_number()); }

  // The specification puts it second; comments before it do no harm.
  void read_format(const std::vector<std::string_view>& tokens) {
    if (format_line_ != 0) fail_here("a second format line (the first is line " + std::to_string(format_line_) + ")");
    format_line_ = lines_.line_number();
    if (tokens.size() != 3 || (tokens[2] != "1.0" && tokens[2] != "1"))
      fail_here("expected 'format ascii 1.0' (or binary_little_endian, binary_big_endian)");
    if (tokens[1] == "ascii") header_.encoding = PlyEncoding::Ascii;
    else if (tokens[1] == "binary_little_endian") header_.encoding = PlyEncoding::BinaryLittleEndian;
    else if (tokens[1] == "binary_big_endian") header_.encoding = PlyEncoding::BinaryBigEndian;
    else fail_here("unknown PLY format " + quote_token(tokens[1]));
  }

  void read_element(const std::vector<std::string_view>& tokens) {
    uint64_t count = 0;
    if (tokens.size() != 3) fail_here("expected 'element NAME COUNT'");
    if (!parse_digits(tokens[2], count) || count > kMaxElementCount)
      fail_here("element count " + quote_token(tokens[2]) + " is not a whole number below 2^32");
    if (header_.find(tokens[1])) fail_here("element '" + std::string(tokens[1]) + "' is declared twice");
    header_.elements.push_back(PlyElement{std::string(tokens[1]), count, {}});
  }

  void read_property(const std::vector<std::string_view>& tokens) {
    if (header_.elements.empty()) fail_here("property declared before any element");
    PlyProperty property;
    bool is_list = tokens.size() == 5 && tokens[1] == "list";
    if (!is_list && tokens.size() != 3) fail_here("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
    property.is_list = is_list;
    property.name = std::string(tokens.back());
    property.type = type_or_fail(tokens[is_list ? 3 : 1]);
    if (is_list) {
      property.count_type = type_or_fail(tokens[2]);
      if (!is_integer(property.count_type)) fail_here("the count type of a list must be an integer type");
    }
    PlyElement& element = header_.elements.back();
    if (element.find(property.name)) fail_here("property '" + property.name + "' is declared twice");
    element.properties.push_back(property);
  }

  PlyType type_or_fail(std::string_view name) {
    std::optional<PlyType> type = parse_type(name);
    if (!type) fail_here("unknown PLY type " + quote_token(name));
    return *type;
  }

  PlyHeader finish() {
    if (format_line_ == 0) fail_here("the PLY header has no format line ('format ascii 1.0' or binary)");
    header_.body_offset = lines_.offset();
    header_.body_line = lines_.line_number() + 1;
    return std::move(header_);
  }

  std::string_view bytes_;
  HeaderLines lines_;
  const std::string& file_;
  PlyHeader header_;
  int format_line_ = 0;  // where the format line was; 0 before it
};

}  // namespace

const PlyProperty* PlyElement::find(std::string_view property_name) const {
  for (const PlyProperty& property : properties) {
    if (property.name == property_name) return &property;
  }
  return nullptr;
}

const PlyElement* PlyHeader::find(std::string_view element_name) const {
  for (const PlyElement& element : elements) {
    if (element.name == element_name) return &element;
  }
  return nullptr;
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& file) {
  return HeaderParser(bytes, file).parse();
}

size_t size_of(PlyType type) {
  switch (type) {
    case PlyType::Int8: case PlyType::UInt8: return 1;
    case PlyType::Int16: case PlyType::UInt16: return 2;
    case PlyType::Int32: case PlyType::UInt32: case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 0;
}

bool is_integer(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

const char* name_of(PlyType type) {
  switch (type) {
    case PlyType::Int8: return "char";
    case PlyType::UInt8: return "uchar";
    case PlyType::Int16: return "short";
    case PlyType::UInt16: return "ushort";
    case PlyType::Int32: return "int";
    case PlyType::UInt32: return "uint";
    case PlyType::Float32: return "float";
    case PlyType::Float64: return "double";
  }
  return "?";
}

const char* name_of(PlyEncoding encoding) {
  switch (encoding) {
    case PlyEncoding::Ascii: return "ascii";
    case PlyEncoding::BinaryLittleEndian: return "binary little-endian";
    case PlyEncoding::BinaryBigEndian: return "binary big-endian";
  }
  return "?";
}

}  // namespace convray::mesh
