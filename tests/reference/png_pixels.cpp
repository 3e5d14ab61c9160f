#include "reference/png_pixels.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>

namespace convray::reference {
namespace {

struct Reader {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::vector<png_bytep> rows;  // here, not on decode's frame, which a longjmp leaves
  ~Reader() {
    if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    if (file) std::fclose(file);
  }
};

void on_error(png_structp png, png_const_charp message) {
  auto* out = static_cast<PngPixels*>(png_get_error_ptr(png));
  out->error = message;
  std::longjmp(png_jmpbuf(png), 1);
}

void on_warning(png_structp, png_const_charp) {}

// The decoding, between libpng's setjmp and any longjmp: `reader` and `out` are set up before
// and only their pointees change here, so they are still valid after a jump; nothing on this
// frame needs a destructor (a jump skips them).
bool decode(Reader* reader, PngPixels* out) {
  if (setjmp(png_jmpbuf(reader->png))) return false;
  png_structp png = reader->png;
  png_infop info = reader->info;
  png_init_io(png, reader->file);
  png_read_info(png, info);
  png_set_expand(png);          // palette and low-bit grey to 8 bits, tRNS to alpha
  png_set_scale_16(png);        // 16-bit samples to 8 bits, rounded
  png_set_strip_alpha(png);
  png_set_gray_to_rgb(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  if (png_get_rowbytes(png, info) != size_t(width) * 3) {
    out->error = "unexpected row size after conversion to 8-bit RGB";
    return false;
  }
  out->rgb.resize(size_t(width) * height * 3);
  reader->rows.resize(height);
  for (png_uint_32 y = 0; y < height; ++y) {
    reader->rows[y] = out->rgb.data() + size_t(y) * width * 3;
  }
  png_read_image(png, reader->rows.data());
  png_read_end(png, nullptr);
  out->width = int(width);
  out->height = int(height);
  return true;
}

}  // namespace

PngPixels read_png_rgb8(const std::string& path) {
  auto out = std::make_unique<PngPixels>();
  auto reader = std::make_unique<Reader>();
  reader->file = std::fopen(path.c_str(), "rb");
  if (!reader->file) {
    out->error = "cannot open " + path;
    return *out;
  }
  reader->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, out.get(), on_error, on_warning);
  if (reader->png) reader->info = png_create_info_struct(reader->png);
  if (!reader->png || !reader->info) {
    out->error = "libpng could not start";
    return *out;
  }
  if (!decode(reader.get(), out.get())) {
    out->rgb.clear();
    out->width = out->height = 0;
    if (out->error.empty()) out->error = "not a readable PNG";
    out->error = path + ": " + out->error;
  }
  return *out;
}

}  // namespace convray::reference
