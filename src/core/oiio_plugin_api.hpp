#pragma once
// The C interface between convray and libconvray_oiio.so, the plugin that holds everything
// convray does with OpenImageIO (src/oiio_plugin/). OpenImageIO pulls in some 250 shared
// libraries (OpenCV, GDAL, ffmpeg, ...) whose loading cost every process a fifth of a second
// before main(); behind a plugin that cost is paid only by the runs that write or check a
// picture in a format other than PNG (core/image_plugin.cpp loads it on first use).
//
// Plain C types, and no exception crosses it: the plugin catches them and reports failures
// by return value and message. Both sides are built from this header, and a plugin from
// another build is refused by its version.
#include <cstddef>

#define CONVRAY_OIIO_PLUGIN_VERSION 2

extern "C" {

// CONVRAY_OIIO_PLUGIN_VERSION of the plugin's build.
using ConvrayOiioVersionFn = int();

// 1 when OpenImageIO has a writer for files named like `path` (by its extension), else 0.
// Touches no file.
using ConvrayOiioCanWriteFn = int(const char* path);

// Writes a width x height RGB picture into `file`, in the format `format_path`'s extension
// names (the temporary being written need not carry the destination's extension). `values`:
// 3 floats per pixel, rows top first, stored as `bits` 8 or 16 bit integers or 32-bit float;
// `color_space` ("sRGB", "Linear" or "") is recorded where the format can say it. Returns 1,
// or 0 with the reason in `message` (`message_size` bytes, null-terminated).
using ConvrayOiioWriteFn = int(const char* format_path, const char* file, int width, int height,
                               int bits, const char* color_space, const float* values,
                               char* message, size_t message_size);

// 1 when `path` opens as an image of this size with at least 3 channels and every pixel reads
// back without error, else 0. Prints nothing.
using ConvrayOiioReadsWholeFn = int(const char* path, int width, int height);

// Reads the image `path` (a scene's image_map) as 4 floats per pixel, rows top first: red,
// green, blue and alpha (grey images repeated into red, green and blue; alpha 1 where the
// file has none). `*values` is allocated with malloc; the caller frees it with free().
// `*linear` is 1 when the file stores linear light (floating-point formats such as .exr and
// .hdr), 0 when its values are display-encoded (8 and 16 bit formats); `*bits` the bits of one
// stored channel (8, 16, 32 ...); `*grey` 1 when the file has one colour channel. Returns 1,
// or 0 with the reason in `message`.
using ConvrayOiioReadFn = int(const char* path, int* width, int* height, int* linear, int* bits,
                              int* grey, float** values, char* message, size_t message_size);

}  // extern "C"

// The exported names, for dlsym.
#define CONVRAY_OIIO_VERSION_SYMBOL "convray_oiio_version"
#define CONVRAY_OIIO_CAN_WRITE_SYMBOL "convray_oiio_can_write"
#define CONVRAY_OIIO_WRITE_SYMBOL "convray_oiio_write"
#define CONVRAY_OIIO_READS_WHOLE_SYMBOL "convray_oiio_reads_whole"
#define CONVRAY_OIIO_READ_SYMBOL "convray_oiio_read"
