#pragma once
// PNG, every render's default format, written by libpng directly (its chunks; the image data
// filtered and deflated on every core by core/png_deflate.hpp): writing a PNG needs none of
// the image libraries behind the other formats (core/image_plugin.hpp), so a render starts
// without loading them.
//
// What is stored is what convray wrote through OpenImageIO before (tests/images/
// png_writer_test.cpp compares the two): 8-bit RGB, no alpha, no interlacing;
//   PixelEncoding::linear   encode_srgb, then quantised; the file says sRGB (an sRGB chunk,
//                           with the gAMA and cHRM chunks PNG asks to go with it)
//   PixelEncoding::display  quantised as given; no colour chunks
#include <cstdint>
#include <string>
#include <vector>

#include "core/image_file.hpp"

namespace convray {

// A value in [0, 1] as an 8-bit level: round(v * 255), halves away from zero, with v * 255
// computed in float; below 0 and NaN give 0, above 1 gives 255. This is OpenImageIO's rule
// for float to uint8, which convray's PNGs always followed.
uint8_t quantize_8bit(float value);

// The whole PNG file in memory. Throws InputError("PATH: cannot write the image: ...") when
// libpng reports an error; `path` only names the file in that message.
std::vector<unsigned char> encode_png(const std::string& path, const ImagePixels& pixels);

}  // namespace convray
