#include "sdl/parse_log.hpp"

#include <algorithm>

namespace convray::sdl {

void ParseLog::note_file(const std::string& path) {
  if (std::find(files.begin(), files.end(), path) == files.end()) files.push_back(path);
}

void ParseLog::note_convolution(const ConvolutionHeader& header) {
  const auto same = [&](const ConvolutionHeader& h) { return same_place(h.loc, header.loc); };
  if (std::none_of(convolutions.begin(), convolutions.end(), same)) {
    convolutions.push_back(header);
  }
}

}  // namespace convray::sdl
