#pragma once
// The picture being rendered: linear RGB, one float triple per pixel, row 0 at the top.
// Each pixel is written by exactly one task, so no locking is needed.
#include <span>
#include <vector>

#include "util/math.hpp"

namespace convray::render {

class Film {
 public:
  Film(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // Pixel (i, j): column i from the left, row j from the top.
  void set(int i, int j, const Vec3& rgb);
  Vec3 at(int i, int j) const;

  // Row-major, top row first, three floats (R, G, B) per pixel: what image_file writes.
  std::span<const float> rgb() const { return rgb_; }

 private:
  size_t index(int i, int j) const { return 3 * (size_t(j) * size_t(width_) + size_t(i)); }

  int width_, height_;
  std::vector<float> rgb_;
};

}  // namespace convray::render
