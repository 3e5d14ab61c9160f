#pragma once
// POV-Ray's partial renders: +SCn +ECn +SRn +ERn (Start_Column, End_Column, Start_Row,
// End_Row) render only a rectangle of the picture, so that one picture can be split among
// processes or machines (docs/render-farm.md). The file written is the whole picture, black
// outside the rectangle, as POV-Ray 3.7 writes it, so the parts of a split add up.
//
// The values, measured on POV-Ray 3.7.0.10 and as its source (View::StartRender) reads them:
//   - a start from 0.0 up to (not including) 1.0 is a fraction of the width or height: the
//     first pixel is int(fraction * size), counted from 0; +SR0.25 at +H48 starts at row 13;
//   - an end from 0.0 to 1.0 (1.0 included) is a fraction too: the last pixel is
//     int(fraction * size) - 1; +ER0.5 at +H48 ends at row 24, +ER1 at the last row;
//   - any other value is a pixel number counted from 1, its fraction dropped: +SR10.7 is row 10;
//   - a first or last pixel outside the picture is an error ("Invalid start column or row",
//     "Invalid end column or row": +SR0 is row 1, but +ER0 and +SR-5 are errors);
//   - a start after the end is no error: nothing is rendered and the picture is all black.
#include <optional>
#include <string>

#include "render/pixel_window.hpp"

namespace convray::app {

// One bound as given, with the argument that gave it ("+SR10", "Start_Row") for messages.
struct PartialBound {
  double value = 0.0;
  std::string what;
};

struct PartialImage {
  std::optional<PartialBound> start_column, end_column, start_row, end_row;

  bool given() const { return start_column || end_column || start_row || end_row; }
};

// The pixels a width x height picture's partial render computes; nullopt when no bound is
// given (the whole picture). Throws UsageError for a bound outside the picture.
std::optional<render::PixelWindow> partial_window(const PartialImage& partial, int width,
                                                  int height);

}  // namespace convray::app
