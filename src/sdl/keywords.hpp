#pragma once
// POV-Ray 3.7's reserved words. The lexer marks an identifier that is one of them as a
// keyword; the words the parser core acts on (directive names, constants, colour keywords,
// built-in functions) also get a `Word` code so that the core dispatches with a switch, not
// string compares. Every other reserved word (sphere, texture, ...) is Word::other: item
// parsers compare its text.
#include <cstdint>
#include <string_view>
#include <vector>

namespace convray::sdl {

// One line per group reads better than one word per line:
// clang-format off
enum class Word : std::uint8_t {
  none,   // not a reserved word: an identifier
  other,  // reserved, handled by the item parsers
  // Directive names.
  include, declare, local, undef, if_, ifdef, ifndef, elseif, else_, end, while_, for_,
  switch_, case_, range, break_, macro, version, debug, warning, error, default_, fopen,
  fclose, read, write, render, statistics,
  // Constants.
  pi, tau, true_, false_, yes, no, on, off, x, y, z, t, u, v, clock, clock_delta, clock_on,
  frame_number, initial_frame, final_frame, initial_clock, final_clock, image_width,
  image_height, input_file_name,
  // Colours.
  color, colour, rgb, rgbf, rgbt, rgbft, srgb, srgbf, srgbt, srgbft, red, green, blue, filter,
  transmit, gray, grey,
  // Float functions (abs .. vdot), vector functions, string functions (concat .. vstr): the
  // parser tests ranges of this order.
  abs, acos, acosh, asin, asinh, atan, atan2, atanh, ceil, cos, cosh, degrees, div, exp, floor,
  int_, ln, log, max, min, mod, pow, radians, select, sin, sinh, sqr, sqrt, tan, tanh,
  bitwise_and, bitwise_or, bitwise_xor, seed, rand, strcmp, strlen, val, asc, file_exists,
  defined, dimensions, dimension_size, vlength, vdot,
  vnormalize, vcross, vrotate, vaxis_rotate,
  concat, str, chr, substr, strupr, strlwr, vstr,
  // Other words of the core's syntax.
  array, mixed, function, internal, optional, deprecated, once,
};
// clang-format on

// The code of a reserved word, Word::none for an ordinary identifier.
Word classify_word(std::string_view text);

// Every reserved word, for "did you mean" suggestions.
const std::vector<std::string_view>& reserved_words();

}  // namespace convray::sdl
