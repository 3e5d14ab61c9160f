#pragma once
// PNG pictures read back by the tests with libpng alone: independent of convray's own PNG
// writer (its deflate streams, palettes and bands), and light to load, where linking
// OpenImageIO (some 250 libraries) cost every test process 0.4 s of start-up.
#include <string>
#include <vector>

namespace convray::reference {

struct PngPixels {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // 8-bit RGB, row after row from the top
  std::string error;               // why the file could not be read (rgb is then empty)
};

// Palettes expanded, grey replicated into red, green and blue, alpha dropped, 16-bit samples
// scaled to 8 bits (rounded), no gamma applied: the values as stored.
PngPixels read_png_rgb8(const std::string& path);

}  // namespace convray::reference
