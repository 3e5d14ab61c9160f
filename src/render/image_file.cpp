#include "render/image_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "util/error.hpp"

namespace convray::render {

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

OIIO::TypeDesc stored_type(const ImageFormat& format) {
  if (format.floating) return OIIO::TypeDesc::FLOAT;
  return format.bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
}

// `.NAME.partial.EXT` next to NAME.EXT: hidden, and keeping the extension, so that
// OpenImageIO picks the same writer for it.
// Asks the kernel to put the file's bytes on the disk (best effort: a failure only loses the
// guarantee across a power cut, never the file).
void flush_to_disk(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

fs::path partial_path_for(const fs::path& target) {
  std::string name = ".";
  name.append(target.stem().string()).append(".partial").append(target.extension().string());
  return target.parent_path() / name;
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
  // Asks OpenImageIO for a writer without touching the disk.
  if (!OIIO::ImageOutput::create(path)) {
    OIIO::geterror();  // clear the message this failure left
    throw InputError({path},
                     "cannot write images of type '." + extension + "' (" + kKnownFormats + ")");
  }
  if (extension == "exr" || extension == "hdr") return {extension, 32, true};
  if (extension == "tif" || extension == "tiff") return {extension, 16, false};
  return {extension, 8, false};
}

void check_image_destination(const std::string& path) {
  image_format_for(path);
  const fs::path folder = fs::path(path).parent_path();
  std::error_code error;
  if (!folder.empty() && !fs::is_directory(folder, error)) {
    throw InputError({path},
                     "cannot write the image: folder '" + folder.string() + "' does not exist");
  }
  if (fs::is_directory(fs::path(path), error)) {
    throw InputError({path}, "cannot write the image: a folder of that name exists");
  }
}

bool image_file_is_complete(const std::string& path, int width, int height) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return false;
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
  if (!in) {
    OIIO::geterror();  // clear the message this failure left
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width != width || spec.height != height || spec.nchannels < 3) return false;
  // Reading every pixel is what finds a truncated file: the header alone can be intact.
  std::vector<float> pixels(size_t(width) * size_t(height) * size_t(spec.nchannels));
  const bool whole = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data());
  if (!whole) in->geterror();
  in->close();
  return whole;
}

void write_image_atomically(const std::string& path, const ImagePixels& pixels) {
  const ImageFormat format = image_format_for(path);
  if (pixels.width < 1 || pixels.height < 1 ||
      pixels.rgb.size() != 3 * size_t(pixels.width) * size_t(pixels.height)) {
    throw std::invalid_argument("write_image_atomically: pixel count does not match the size");
  }
  const std::vector<float> values = encoded_for(format, pixels);
  const fs::path target(path);
  const fs::path partial = partial_path_for(target);

  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(pixels.width, pixels.height, 3, stored_type(format));
  if (format.floating) {
    spec.attribute("oiio:ColorSpace", "Linear");
  } else if (pixels.encoding == PixelEncoding::linear) {
    spec.attribute("oiio:ColorSpace", "sRGB");  // what encoded_for made of it
  }
  const bool written = out && out->open(partial.string(), spec) &&
                       out->write_image(OIIO::TypeDesc::FLOAT, values.data()) && out->close();
  std::string problem = written ? "" : (out ? out->geterror() : OIIO::geterror());
  out.reset();  // closes the partial file, if still open, before it is removed

  std::error_code error;
  if (written) {
    flush_to_disk(partial);  // a crash after the rename must not leave an empty "complete" file
    fs::rename(partial, target, error);
    if (error) problem = error.message();
  }
  if (!written || error) {
    std::error_code ignored;
    fs::remove(partial, ignored);
    if (problem.empty()) problem = "the writer gave no reason";
    throw InputError({path}, "cannot write the image: " + problem);
  }
}

}  // namespace convray::render
