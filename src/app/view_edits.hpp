#pragma once
// `convray view`'s live edits of a convolution header: r and R make the radius smaller and
// larger by a tenth, o and O move the offset by a twentieth of the radius, each kept to three
// significant digits (values a person would type) and to 0 <= offset < radius.
#include <vector>

#include "sdl/parse_log.hpp"

namespace convray::app {

// `header` after the key (r, R, o, O); its offset is always set.
sdl::ConvolutionHeader edited_header(const sdl::ConvolutionHeader& header, char key);

// Replaces the edit of the same header in `edits`, or adds it.
void set_edit(std::vector<sdl::ConvolutionEdit>& edits, const sdl::ConvolutionHeader& header);

// `value` to three significant digits.
double three_digits(double value);

}  // namespace convray::app
