#pragma once
// Writing pictures, the format chosen by the file name's extension:
//
//   .png           8 bits per channel, sRGB-encoded, by libpng (core/png_writer.hpp)
//   any other format OpenImageIO writes, through a plugin loaded on first use
//   (core/image_plugin.hpp), so that a PNG render never loads OpenImageIO:
//   .jpg .ppm .bmp .tga ...  8 bits per channel, sRGB-encoded
//   .tif .tiff     16 bits per channel, sRGB-encoded
//   .exr .hdr      32-bit float (.hdr: RGBE), linear: the renderer's values untouched
//
// Renderers compute linear light (PixelEncoding::linear); integer formats get the sRGB
// transfer curve (IEC 61966-2-1) applied before quantising, the way image viewers expect
// them. Pictures whose values are already meant for display (`convray slice`'s colour ramp)
// say PixelEncoding::display and are stored as they are.
//
// The file appears complete or not at all (util/atomic_file.hpp): the encoded bytes go to a
// fresh temporary beside NAME.EXT, every write checked, which is renamed over NAME.EXT once
// synced, and removed on any failure (a full disk, a kill), leaving the previous file intact.
#include <span>
#include <string>

namespace convray {

enum class PixelEncoding {
  linear,   // linear light: sRGB-encoded for integer formats
  display,  // already display-referred: stored as given
};

struct ImagePixels {
  int width = 0, height = 0;
  std::span<const float> rgb;  // row-major, top row first, 3 floats per pixel
  PixelEncoding encoding = PixelEncoding::linear;
};

struct ImageFormat {
  std::string extension;  // lower case, without the dot: "png"
  int bits = 8;           // per channel: 8, 16 or 32
  bool floating = false;  // 32-bit float, linear
};

// The format a file of this name is written in. Throws InputError ("PATH: ...") when the name
// has no extension or OpenImageIO has no writer for it (asked only for names not ending .png).
ImageFormat image_format_for(const std::string& path);

// Checks, before any work is done, that `path` can be written: a known format, and a folder
// that exists. Throws InputError otherwise.
void check_image_destination(const std::string& path);

// Writes the picture as described above. Throws InputError when the file cannot be written
// (unknown format, missing folder, disk full, ...); no file is left behind then.
void write_image_atomically(const std::string& path, const ImagePixels& pixels);

// Whether `path` holds a whole image of this size that reads back without error: `+C`
// (continue) trusts such a frame and skips it. A missing, truncated or damaged file, or one of
// another size, is not complete.
// PNG is checked here; other formats are read back by the plugin, and a missing plugin is an
// InputError, as it is for image_format_for.
bool image_file_is_complete(const std::string& path, int width, int height);

// The sRGB transfer curve, for linear values clamped to [0, 1].
float encode_srgb(float linear);

}  // namespace convray
