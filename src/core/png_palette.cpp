#include "core/png_palette.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>

namespace convray {

namespace {

void on_error(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void on_warning(png_structp, png_const_charp) {}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

// Only C objects live in this frame, so libpng's longjmp on an error skips no destructor:
// `rows` is sized by the caller and `indices` filled once the rows are read.
bool read_rows(png_structp png, png_infop info, std::FILE* file, int width, int height,
               std::vector<png_byte>& rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_read_info(png, info);
  if (png_get_color_type(png, info) != PNG_COLOR_TYPE_PALETTE ||
      int(png_get_image_width(png, info)) != width ||
      int(png_get_image_height(png, info)) != height) {
    return false;
  }
  png_set_packing(png);  // 1, 2 and 4 bit indices to one byte each
  png_read_update_info(png, info);
  const int passes = png_set_interlace_handling(png);
  for (int pass = 0; pass < passes; ++pass) {
    for (int y = 0; y < height; ++y) png_read_row(png, &rows[size_t(y) * size_t(width)], nullptr);
  }
  return true;
}

}  // namespace

std::vector<int> png_palette_indices(const std::string& path, int width, int height) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file || width < 1 || height < 1) return {};
  png_byte signature[8];
  if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0) return {};
  std::rewind(file.get());
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, on_error, on_warning);
  if (!png) return {};
  png_infop info = png_create_info_struct(png);
  std::vector<png_byte> rows(size_t(width) * size_t(height));
  const bool read = info && read_rows(png, info, file.get(), width, height, rows);
  png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
  if (!read) return {};
  return std::vector<int>(rows.begin(), rows.end());
}

}  // namespace convray
