#include "core/image_file.hpp"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "core/image_plugin.hpp"
#include "core/png_writer.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace convray {

namespace fs = std::filesystem;

namespace {

constexpr const char* kKnownFormats = "use .png, .exr or .tif";

std::string lower_extension(const fs::path& path) {
  std::string extension = path.extension().string();
  if (!extension.empty()) extension.erase(0, 1);  // the dot
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

// The values handed to OpenImageIO: sRGB-encoded where an integer format stores linear light.
std::vector<float> encoded_for(const ImageFormat& format, const ImagePixels& pixels) {
  std::vector<float> values(pixels.rgb.begin(), pixels.rgb.end());
  if (!format.floating && pixels.encoding == PixelEncoding::linear) {
    for (float& v : values) v = encode_srgb(v);
  }
  return values;
}

}  // namespace

float encode_srgb(float linear) {
  if (!(linear > 0.0f)) return 0.0f;  // also NaN
  if (linear >= 1.0f) return 1.0f;
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

ImageFormat image_format_for(const std::string& path) {
  const std::string extension = lower_extension(fs::path(path));
  if (extension.empty()) {
    throw InputError({path}, "the image name needs an extension to choose its format (" +
                                 std::string(kKnownFormats) + ")");
  }
  // PNG is written here (core/png_writer.hpp); for any other extension OpenImageIO is asked
  // for a writer, without touching the disk.
  if (extension != "png" && !image_plugin::can_write(path)) {
    throw InputError({path},
                     "cannot write images of type '." + extension + "' (" + kKnownFormats + ")");
  }
  if (extension == "exr" || extension == "hdr") return {extension, 32, true};
  if (extension == "tif" || extension == "tiff") return {extension, 16, false};
  return {extension, 8, false};
}

void check_image_destination(const std::string& path) {
  image_format_for(path);
  check_writable_destination(path, "the image");
}

namespace {

uint32_t big_endian_32(const unsigned char* b) {
  return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | uint32_t(b[3]);
}

// A PNG checked by its structure (ISO/IEC 15948): the signature, an IHDR of this size, every
// chunk's CRC, and IEND as the last chunk, ending the file. This finds a truncated or damaged
// file without decoding it, so libpng prints nothing to the terminal (`+C` over a folder of
// frames stays quiet).
bool png_is_whole(const std::string& path, int width, int height) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < 8 || std::memcmp(data, kSignature, 8) != 0) return false;
  size_t at = 8;
  bool first = true;
  while (at + 12 <= bytes.size()) {
    const uint32_t length = big_endian_32(data + at);
    if (length > bytes.size() - at - 12) return false;  // the chunk runs past the end
    const unsigned char* type = data + at + 4;
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), type, uInt(length + 4));
    if (crc != big_endian_32(type + 4 + length)) return false;
    if (first) {
      if (std::memcmp(type, "IHDR", 4) != 0 || length < 8) return false;
      if (big_endian_32(type + 4) != uint32_t(width) || big_endian_32(type + 8) != uint32_t(height))
        return false;
      first = false;
    }
    at += 12 + length;
    if (std::memcmp(type, "IEND", 4) == 0) return at == bytes.size();
  }
  return false;
}

}  // namespace

bool image_file_is_complete(const std::string& path, int width, int height) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return false;
  if (lower_extension(fs::path(path)) == "png") return png_is_whole(path, width, height);
  return image_plugin::reads_whole(path, width, height);
}

namespace {

// What the plugin records as the file's colour space, where the format can say it.
std::string color_space_of(const ImageFormat& format, const ImagePixels& pixels) {
  if (format.floating) return "Linear";
  return pixels.encoding == PixelEncoding::linear ? "sRGB" : "";  // what encoded_for made of it
}

// Every format but PNG is written by OpenImageIO (in the plugin), which opens the file by name:
// it writes into a private folder, and the result is read back whole before it replaces
// anything, since such a writer may not report a full disk. (OpenImageIO 2.4's TIFF writer,
// for one, claims to write into memory but leaves out the image length.)
void write_by_name(const std::string& path, const ImageFormat& format, const ImagePixels& pixels) {
  const std::vector<float> values = encoded_for(format, pixels);
  AtomicFileByName file(path, "the image", "image." + format.extension);
  image_plugin::write(path, file.path().string(), pixels.width, pixels.height, format.bits,
                      color_space_of(format, pixels), values.data());
  if (!image_file_is_complete(file.path().string(), pixels.width, pixels.height)) {
    throw InputError({path},
                     "cannot write the image: the file written does not read back whole "
                     "(is the disk full?)");
  }
  file.commit();
}

}  // namespace

void write_image_atomically(const std::string& path, const ImagePixels& pixels) {
  const ImageFormat format = image_format_for(path);
  if (pixels.width < 1 || pixels.height < 1 ||
      pixels.rgb.size() != 3 * size_t(pixels.width) * size_t(pixels.height)) {
    throw std::invalid_argument("write_image_atomically: pixel count does not match the size");
  }
  if (format.extension != "png") return write_by_name(path, format, pixels);
  // PNG, every render's default, is encoded in memory; the bytes then reach the disk through
  // AtomicFile, every write checked.
  const std::vector<unsigned char> bytes = encode_png(path, pixels);
  write_file_atomically(path,
                        std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                        "the image");
}

}  // namespace convray
