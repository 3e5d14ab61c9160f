#include "display/preview_image.hpp"

#include "core/srgb_levels.hpp"

namespace convray::display {

PreviewImage::PreviewImage(const render::PixelWindow& shown, PreviewSize size)
    : shown_(shown), size_(size), levels_(3 * size_t(size.width) * size_t(size.height), 0) {}

void PreviewImage::put(const render::PixelWindow& area, std::span<const float> rgb) {
  const render::PixelWindow inside = area.intersection(shown_);
  if (inside.empty()) return;
  const int source_w = shown_.x1 - shown_.x0, source_h = shown_.y1 - shown_.y0;
  const ShownRange cols =
      shown_range(inside.x0 - shown_.x0, inside.x1 - shown_.x0, size_.width, source_w);
  const ShownRange rows =
      shown_range(inside.y0 - shown_.y0, inside.y1 - shown_.y0, size_.height, source_h);
  const size_t area_w = size_t(area.x1 - area.x0);
  std::lock_guard<std::mutex> hold(lock_);
  for (int v = rows.first; v < rows.last; ++v) {
    const int j = shown_.y0 + source_of(v, size_.height, source_h);
    for (int u = cols.first; u < cols.last; ++u) {
      const int i = shown_.x0 + source_of(u, size_.width, source_w);
      const size_t from = 3 * (size_t(j - area.y0) * area_w + size_t(i - area.x0));
      const size_t to = 3 * (size_t(v) * size_t(size_.width) + size_t(u));
      for (int c = 0; c < 3; ++c) levels_[to + c] = srgb_level(rgb[from + c]);
    }
  }
  changed_ = true;
}

bool PreviewImage::take_if_changed(std::vector<uint8_t>& out) {
  std::lock_guard<std::mutex> hold(lock_);
  if (!changed_) return false;
  out = levels_;
  changed_ = false;
  return true;
}

void PreviewImage::mark_changed() {
  std::lock_guard<std::mutex> hold(lock_);
  changed_ = true;
}

}  // namespace convray::display
