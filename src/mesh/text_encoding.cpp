#include "mesh/text_encoding.hpp"

#include <cstdint>

#include "mesh/load_error.hpp"

namespace convray::mesh {
namespace {

void append_utf8(uint32_t code, std::string& out) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xc0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3f));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xe0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (code & 0x3f));
  } else {
    out += static_cast<char>(0xf0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3f));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (code & 0x3f));
  }
}

// UTF-16 without its byte-order mark.
std::string from_utf16(std::string_view bytes, bool big_endian, const std::string& file) {
  if (bytes.size() % 2 != 0) fail(file, "the UTF-16 text has an odd number of bytes (the file is truncated)");
  auto unit = [&](size_t i) {
    const auto hi = static_cast<unsigned char>(bytes[big_endian ? i : i + 1]);
    const auto lo = static_cast<unsigned char>(bytes[big_endian ? i + 1 : i]);
    return static_cast<uint32_t>(hi << 8 | lo);
  };
  std::string text;
  text.reserve(bytes.size() / 2);
  for (size_t i = 0; i < bytes.size(); i += 2) {
    uint32_t code = unit(i);
    if (code >= 0xd800 && code < 0xdc00 && i + 2 < bytes.size() && unit(i + 2) >= 0xdc00 && unit(i + 2) < 0xe000) {
      code = 0x10000 + ((code - 0xd800) << 10) + (unit(i + 2) - 0xdc00);
      i += 2;
    } else if (code >= 0xd800 && code < 0xe000) {
      fail(file, "the UTF-16 text has an unpaired surrogate at offset " + std::to_string(i));
    }
    append_utf8(code, text);
  }
  return text;
}

}  // namespace

std::string_view as_utf8(std::string_view bytes, std::string& storage, const std::string& file) {
  if (bytes.substr(0, 3) == "\xef\xbb\xbf") return bytes.substr(3);
  if (bytes.substr(0, 2) == "\xff\xfe") return storage = from_utf16(bytes.substr(2), false, file);
  if (bytes.substr(0, 2) == "\xfe\xff") return storage = from_utf16(bytes.substr(2), true, file);
  return bytes;
}

}  // namespace convray::mesh
