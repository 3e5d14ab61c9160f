#pragma once
// The palette indices of a PNG palette image (POV-Ray's height_field takes a palette image's
// index, not its colour, as the height; OpenImageIO expands palettes to colours).
#include <string>
#include <vector>

namespace convray {

// One index per pixel, rows top first, when `path` is a PNG palette image (colour type 3);
// empty for any other file (another format, a PNG without palette, one libpng cannot read).
std::vector<int> png_palette_indices(const std::string& path, int width, int height);

}  // namespace convray
