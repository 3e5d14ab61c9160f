#pragma once
// OpenImageIO's formats, reached through libconvray_oiio.so (core/oiio_plugin_api.hpp),
// which is loaded on the first call of any function here and stays loaded. It is looked for
// beside the running program (/proc/self/exe): build/convray loads build/libconvray_oiio.so.
//
// Every function throws InputError("PATH: ...", naming the plugin's file and the loader's
// reason) when the plugin cannot be loaded; `path` is the image the caller was working on.
#include <string>
#include <vector>

namespace convray::image_plugin {

// Whether OpenImageIO has a writer for files named like `path`. Touches no file.
bool can_write(const std::string& path);

// Writes `file` in the format of `format_path`'s extension (see ConvrayOiioWriteFn); throws
// InputError({format_path}, "cannot write the image: REASON") when the writer fails.
void write(const std::string& format_path, const std::string& file, int width, int height, int bits,
           const std::string& color_space, const float* values);

// Whether `path` reads back whole as an image of this size (see ConvrayOiioReadsWholeFn).
bool reads_whole(const std::string& path, int width, int height);

// An image read for a scene: RGBA floats as the file stores them, rows top first.
struct ReadImage {
  int width = 0, height = 0;
  bool linear = false;        // the file stores linear light (.exr, .hdr); else display-encoded
  int bits = 8;               // of one stored channel
  bool grey = false;          // one colour channel (repeated into red, green and blue)
  std::vector<float> rgba;    // 4 per pixel
};

// Reads `path` (see ConvrayOiioReadFn); throws InputError({path}, "cannot read the image:
// REASON") when it cannot be read.
ReadImage read(const std::string& path);

}  // namespace convray::image_plugin
