#pragma once
// Where a picture's pixels land in the preview window (POV-Ray's +D): the window is the
// picture's size, or the part a partial render computes, scaled down to fit the largest
// window we open, its aspect kept. No SDL here: tests check the arithmetic directly.
#include "render/pixel_window.hpp"

namespace convray::display {

struct PreviewSize {
  int width = 0, height = 0;
};

// The largest window the preview opens: it fits a common screen with room for a title bar.
constexpr PreviewSize kLargestPreview{1280, 1024};

// The window for a `width` x `height` picture: the picture's own size when it fits in
// `largest`, else scaled down by one factor for both axes (at least 1 x 1 pixel).
PreviewSize fit_preview(int width, int height, PreviewSize largest = kLargestPreview);

// The source pixel (0 .. source - 1) a window pixel shows: the nearest one to its centre, so
// that an unscaled window shows every pixel as it is.
int source_of(int shown, int shown_size, int source_size);

// The window pixels [first, last) whose source pixels lie in [from, to).
struct ShownRange {
  int first = 0, last = 0;
};
ShownRange shown_range(int from, int to, int shown_size, int source_size);

}  // namespace convray::display
