// libconvray_oiio.so: every image format but PNG, through OpenImageIO (the interface and why
// it is a plugin: core/oiio_plugin_api.hpp). convray's own rules (which format stores how
// many bits, which colour space, the atomic write around it) stay in core/image_file.cpp;
// this file only turns those decisions into OpenImageIO calls.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "core/oiio_plugin_api.hpp"

#define CONVRAY_EXPORT extern "C" __attribute__((visibility("default")))

namespace {

OIIO::TypeDesc stored_type(int bits) {
  if (bits == 32) return OIIO::TypeDesc::FLOAT;
  return bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
}

void copy_message(const std::string& text, char* message, size_t message_size) {
  if (message && message_size > 0) std::snprintf(message, message_size, "%s", text.c_str());
}

std::string write_image(const char* format_path, const char* file, int width, int height, int bits,
                        const char* color_space, const float* values) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(format_path);
  if (!out) {
    const std::string problem = OIIO::geterror();
    return problem.empty() ? "OpenImageIO has no writer for it" : problem;
  }
  OIIO::ImageSpec spec(width, height, 3, stored_type(bits));
  if (color_space && *color_space) spec.attribute("oiio:ColorSpace", color_space);
  const bool written =
      out->open(file, spec) && out->write_image(OIIO::TypeDesc::FLOAT, values) && out->close();
  if (written) return "";
  const std::string problem = out->geterror();
  return problem.empty() ? "the writer gave no reason" : problem;
}

// The pixels of `in` as RGBA floats in `rgba` (4 per pixel); "" or the reason it failed.
std::string read_rgba(OIIO::ImageInput& in, std::vector<float>& rgba) {
  const OIIO::ImageSpec& spec = in.spec();
  const int channels = spec.nchannels;
  if (channels < 1) return "the image has no channels";
  const size_t count = size_t(spec.width) * size_t(spec.height);
  std::vector<float> stored(count * size_t(channels));
  if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, stored.data())) {
    const std::string problem = in.geterror();
    return problem.empty() ? "the reader gave no reason" : problem;
  }
  // Grey (1 channel), grey and alpha (2), RGB (3), RGBA (4 or more: the first four).
  const bool grey = channels < 3;
  const int alpha = channels == 2 ? 1 : channels >= 4 ? 3 : -1;
  rgba.resize(count * 4);
  for (size_t k = 0; k < count; ++k) {
    const float* from = &stored[k * size_t(channels)];
    float* to = &rgba[k * 4];
    for (int c = 0; c < 3; ++c) to[c] = from[grey ? 0 : c];
    to[3] = alpha >= 0 ? from[alpha] : 1.0f;
  }
  return "";
}

}  // namespace

CONVRAY_EXPORT int convray_oiio_version() { return CONVRAY_OIIO_PLUGIN_VERSION; }

CONVRAY_EXPORT int convray_oiio_can_write(const char* path) {
  try {
    if (OIIO::ImageOutput::create(path)) return 1;
    OIIO::geterror();  // clear the message this failure left
  } catch (const std::exception&) {
  }
  return 0;
}

CONVRAY_EXPORT int convray_oiio_write(const char* format_path, const char* file, int width,
                                      int height, int bits, const char* color_space,
                                      const float* values, char* message, size_t message_size) {
  try {
    const std::string problem =
        write_image(format_path, file, width, height, bits, color_space, values);
    copy_message(problem, message, message_size);
    return problem.empty() ? 1 : 0;
  } catch (const std::exception& e) {
    copy_message(e.what(), message, message_size);
    return 0;
  }
}

CONVRAY_EXPORT int convray_oiio_reads_whole(const char* path, int width, int height) {
  try {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
      OIIO::geterror();  // clear the message this failure left
      return 0;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width != width || spec.height != height || spec.nchannels < 3) return 0;
    // Reading every pixel is what finds a truncated file: the header alone can be intact.
    std::vector<float> pixels(size_t(width) * size_t(height) * size_t(spec.nchannels));
    const bool whole =
        in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data());
    if (!whole) in->geterror();
    in->close();
    return whole ? 1 : 0;
  } catch (const std::exception&) {
    return 0;
  }
}

CONVRAY_EXPORT int convray_oiio_read(const char* path, int* width, int* height, int* linear,
                                     int* bits, int* grey, float** values, char* message,
                                     size_t message_size) {
  *values = nullptr;
  try {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
      const std::string problem = OIIO::geterror();
      copy_message(problem.empty() ? "OpenImageIO cannot read it" : problem, message, message_size);
      return 0;
    }
    std::vector<float> rgba;
    const std::string problem = read_rgba(*in, rgba);
    const OIIO::ImageSpec spec = in->spec();
    in->close();
    if (!problem.empty()) {
      copy_message(problem, message, message_size);
      return 0;
    }
    *width = spec.width;
    *height = spec.height;
    *linear = spec.format.is_floating_point() ? 1 : 0;
    *bits = int(spec.format.size()) * 8;
    *grey = spec.nchannels < 3 ? 1 : 0;
    *values = static_cast<float*>(std::malloc(rgba.size() * sizeof(float)));
    if (!*values) {
      copy_message("out of memory", message, message_size);
      return 0;
    }
    std::copy(rgba.begin(), rgba.end(), *values);
    return 1;
  } catch (const std::exception& e) {
    copy_message(e.what(), message, message_size);
    return 0;
  }
}
