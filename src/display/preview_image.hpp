#pragma once
// The preview window's picture: 8-bit sRGB levels, one byte per channel, the window's size.
// Tiles arrive from the render's threads in linear light and are encoded exactly as the PNG
// writer encodes the file (core/srgb_levels.hpp), so an unscaled window shows the
// file's bytes. No SDL here: the window (sdl_window.hpp) copies it out under the lock.
#include <cstdint>
#include <mutex>
#include <span>
#include <vector>

#include "display/preview_layout.hpp"
#include "render/pixel_window.hpp"

namespace convray::display {

class PreviewImage {
 public:
  // Shows the pixels `shown` of the picture (the whole picture, or a partial render's
  // window) in a `size` window.
  PreviewImage(const render::PixelWindow& shown, PreviewSize size);

  PreviewSize size() const { return size_; }

  // The pixels of `area` (in the picture's coordinates), row-major, three linear floats
  // each. Thread safe; pixels outside the shown part are ignored.
  void put(const render::PixelWindow& area, std::span<const float> rgb);

  // Copies the levels (width * height * 3 bytes, top row first) into `out` if they changed
  // since the last copy; false, and `out` untouched, if not. Thread safe.
  bool take_if_changed(std::vector<uint8_t>& out);

  // Marks the picture as changed, so that the next take_if_changed copies it (the window was
  // uncovered, say).
  void mark_changed();

 private:
  render::PixelWindow shown_;
  PreviewSize size_;
  std::mutex lock_;
  std::vector<uint8_t> levels_;
  bool changed_ = true;
};

}  // namespace convray::display
