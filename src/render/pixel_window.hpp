#pragma once
// A rectangle of a picture's pixels, [x0, x1) x [y0, y1), row 0 at the top: the part a
// partial render (POV-Ray's +SC/+EC/+SR/+ER, app/partial_image.hpp) computes. Empty when
// x1 <= x0 or y1 <= y0 (POV-Ray renders nothing then and writes a black picture).
#include <algorithm>
#include <cstdint>

namespace convray::render {

struct PixelWindow {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  bool empty() const { return x1 <= x0 || y1 <= y0; }
  uint64_t pixels() const { return empty() ? 0 : uint64_t(x1 - x0) * uint64_t(y1 - y0); }
  bool contains(int i, int j) const { return i >= x0 && i < x1 && j >= y0 && j < y1; }

  // The window grown by `margin` pixels on every side, kept within a width x height picture.
  PixelWindow grown(int margin, int width, int height) const {
    if (empty()) return *this;
    return {std::max(x0 - margin, 0), std::max(y0 - margin, 0), std::min(x1 + margin, width),
            std::min(y1 + margin, height)};
  }

  PixelWindow intersection(const PixelWindow& o) const {
    return {std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
  }
};

}  // namespace convray::render
