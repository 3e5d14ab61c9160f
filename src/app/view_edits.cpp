#include "app/view_edits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "app/view_session.hpp"

namespace convray::app {

double three_digits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return std::strtod(text, nullptr);
}

sdl::ConvolutionHeader edited_header(const sdl::ConvolutionHeader& header, char key) {
  sdl::ConvolutionHeader h = header;
  double offset = header_offset(header);
  if (key == 'r' || key == 'R') {
    h.radius = three_digits(h.radius * (key == 'R' ? 1.1 : 1.0 / 1.1));
  } else if (key == 'o' || key == 'O') {
    offset = three_digits(offset + (key == 'O' ? 0.05 : -0.05) * h.radius);
  }
  // The language's rule: 0 <= offset < radius (a larger offset leaves no surface).
  offset = std::clamp(offset, 0.0, three_digits(0.95 * h.radius));
  if (offset >= h.radius) offset = 0.0;
  h.offset = offset;
  h.threshold.reset();
  return h;
}

void set_edit(std::vector<sdl::ConvolutionEdit>& edits, const sdl::ConvolutionHeader& header) {
  const sdl::ConvolutionEdit edit{header.loc, header.radius, *header.offset};
  for (sdl::ConvolutionEdit& e : edits) {
    if (sdl::same_place(e.loc, edit.loc)) return void(e = edit);
  }
  edits.push_back(edit);
}

}  // namespace convray::app
