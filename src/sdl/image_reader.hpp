#pragma once
// The pictures an image_map names: the scene language does not decode image files; the
// program (app/) hands the parser a reader (ParseOptions::image_reader).
#include <string>
#include <vector>

namespace convray::sdl {

struct ImageFile {
  int width = 0, height = 0;
  bool linear = false;      // the file stores linear light (.exr, .hdr); else display-encoded
  int bits = 8;             // of one stored channel
  bool grey = false;        // one colour channel (repeated into red, green and blue)
  std::vector<float> rgba;  // 4 floats per pixel, rows top first, as the file stores them
  // A palette image's indices, one per pixel (rows top first); empty for other images.
  std::vector<int> palette_indices;
};

class ImageReader {
 public:
  virtual ~ImageReader() = default;
  // Throws InputError({path}, reason) when the file cannot be read.
  virtual ImageFile read(const std::string& path) const = 0;
};

}  // namespace convray::sdl
