#pragma once
// What one parse read, for `convray view` (docs/view.md), which watches the files a scene
// read and edits its convolution headers live: a parse given a ParseLog
// (ParseOptions::log) notes there every file it resolved and every `convolution { }` header
// it read; and ParseOptions::convolution_edits replace some headers' radius and offset, as
// if the scene said them. A parse without either is unchanged.
#include <optional>
#include <string>
#include <vector>

#include "field/kernel.hpp"
#include "util/error.hpp"

namespace convray::sdl {

// A convolution object's own settings, as its header gave them (after any edit).
struct ConvolutionHeader {
  SourceLoc loc;  // of the `convolution` keyword: the header's identity
  double radius = 1.0, strength = 1.0;
  std::optional<double> offset, threshold;  // as written; neither: offset R / 2
  field::Kernel kernel;
};

struct ParseLog {
  // Every file resolved (includes, meshes, image maps, fonts, height fields, file_exists),
  // in the order first read, and where a file not found was looked for; the scene file
  // itself is not listed.
  std::vector<std::string> files;
  // Each header read, once per location (a macro's object read twice is listed once).
  std::vector<ConvolutionHeader> convolutions;

  void note_file(const std::string& path);
  void note_convolution(const ConvolutionHeader& header);
};

// The radius and offset of the convolution whose keyword is at (file, line, column).
struct ConvolutionEdit {
  SourceLoc loc;
  double radius = 1.0, offset = 0.5;
};

// Whether two locations name the same place.
inline bool same_place(const SourceLoc& a, const SourceLoc& b) {
  return a.line == b.line && a.column == b.column && a.file == b.file;
}

}  // namespace convray::sdl
