#include "core/png_writer.hpp"

#include <png.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <new>
#include <stdexcept>

#include "core/png_deflate.hpp"
#include "core/srgb_levels.hpp"
#include "util/error.hpp"

namespace convray {

uint8_t quantize_8bit(float value) {
  const float scaled = value * 255.0f;  // in float, as OpenImageIO computes it
  if (!(scaled > 0.0f)) return 0;       // also NaN
  if (scaled >= 255.0f) return 255;
  return uint8_t(std::round(scaled));  // halves away from zero
}

namespace {

// The largest IDAT chunk written (PNG allows 2^31 - 1 bytes).
constexpr size_t kMaxChunk = size_t{1} << 30;
// The fewest bytes of pixels worth a band of their own.
constexpr size_t kBandBytes = size_t{1} << 16;

// What libpng's callbacks reach: where the bytes go and the error they ended with. libpng is
// C: an exception must not unwind through it, so errors are recorded here and leave through
// png_longjmp to the setjmp in run_libpng.
struct Sink {
  std::vector<unsigned char>* bytes = nullptr;
  char message[200] = "";
};

void on_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<Sink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message ? message : "");
  png_longjmp(png, 1);
}

// libpng's default prints warnings on the terminal; none of them concerns a file we write.
void on_warning(png_structp, png_const_charp) {}

void on_write(png_structp png, png_bytep data, size_t length) {
  auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
  bool out_of_memory = false;
  try {
    sink->bytes->insert(sink->bytes->end(), data, data + length);
  } catch (const std::bad_alloc&) {
    out_of_memory = true;  // png_error after the handler: no longjmp out of a catch block
  }
  if (out_of_memory) png_error(png, "out of memory");
}

void on_flush(png_structp) {}

// The encoding proper. Only C objects live in this frame, so the longjmp of on_error skips
// no destructor; returns false when libpng reported an error.
bool run_libpng(png_structp png, png_infop info, Sink* sink, const ImagePixels& pixels,
                const std::vector<unsigned char>& image_data) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, sink, on_write, on_flush);
  png_set_IHDR(png, info, png_uint_32(pixels.width), png_uint_32(pixels.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (pixels.encoding == PixelEncoding::linear) {
    // The chunks OpenImageIO wrote for an sRGB picture: sRGB (absolute colorimetric intent)
    // and the gAMA and cHRM values that the PNG specification pairs with it.
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
  }
  png_write_info(png, info);
  // The image data made beforehand (core/png_deflate.hpp), written as chunks of their own.
  for (size_t at = 0; at < image_data.size(); at += kMaxChunk) {
    const size_t size = std::min(kMaxChunk, image_data.size() - at);
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IDAT"), image_data.data() + at, size);
  }
  png_write_chunk(png, reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
  return true;
}

// The 8-bit levels the file stores, row after row, a run of rows on each core. A channel's
// level is kept for the next pixel, which often has the same value (a background, a flat
// colour): encode_srgb's pow took 10 of the 80 ms that the dragon's 800x600 picture took to
// write; the others come from srgb_levels' table (its pow and round were still 9 of the soup's
// 17 ms).
std::vector<unsigned char> levels_of(const ImagePixels& pixels) {
  std::vector<unsigned char> levels(pixels.rgb.size());
  const bool linear = pixels.encoding == PixelEncoding::linear;
  const size_t row_values = 3 * size_t(pixels.width);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, size_t(pixels.height)), [&](const auto& rows) {
    // 0 is level 0 either way; equal values give equal levels (-0 and 0 both give 0; NaN is
    // never equal, and is encoded each time).
    float last_value[3] = {0.0f, 0.0f, 0.0f};
    unsigned char last_level[3] = {0, 0, 0};
    for (size_t k = rows.begin() * row_values; k < rows.end() * row_values; ++k) {
      const float v = pixels.rgb[k];
      const size_t channel = k % 3;
      if (!(v == last_value[channel])) {
        last_value[channel] = v;
        last_level[channel] = linear ? srgb_level(v) : quantize_8bit(v);
      }
      levels[k] = last_level[channel];
    }
  });
  return levels;
}

}  // namespace

std::vector<unsigned char> encode_png(const std::string& path, const ImagePixels& pixels) {
  const std::vector<unsigned char> levels = levels_of(pixels);
  const size_t row_bytes = 3 * size_t(pixels.width), height = size_t(pixels.height);
  // Paeth on every row and zlib's level 3: the dragon's 800x600 picture in 32 ms instead of
  // 75 (libpng's default tries five filters per row, then level 6), for a file 7 % larger;
  // in bands on every core (a band at least kBandBytes of pixels) and the levels too, the
  // whole write 16 ms on two cores instead of 25-34.
  const size_t bands = std::min(size_t(std::max(1, tbb::this_task_arena::max_concurrency())),
                                std::max<size_t>(1, row_bytes * height / kBandBytes));
  std::vector<unsigned char> image_data;
  try {
    image_data = png_image_data(levels.data(), row_bytes, height, 3, 3, bands);
  } catch (const std::runtime_error& e) {
    throw InputError({path}, std::string("cannot write the image: ") + e.what());
  }
  std::vector<unsigned char> bytes;
  Sink sink;
  sink.bytes = &bytes;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool written = info && run_libpng(png, info, &sink, pixels, image_data);
  png_destroy_write_struct(png ? &png : nullptr, info ? &info : nullptr);
  if (!written) {
    const std::string reason = sink.message[0] ? sink.message : "libpng could not start";
    throw InputError({path}, "cannot write the image: " + reason);
  }
  return bytes;
}

}  // namespace convray
