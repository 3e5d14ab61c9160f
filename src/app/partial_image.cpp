#include "app/partial_image.hpp"

#include <cmath>

#include "app/short_number.hpp"
#include "app/usage_error.hpp"

namespace convray::app {

namespace {

// int() of POV-Ray's C++: towards zero; the values are clamped first so that the cast is
// defined for any finite value (anything beyond the limit is outside every picture anyway).
int truncated(double v) { return int(std::trunc(std::fmax(std::fmin(v, 1e9), -1e9))); }

// The first pixel (from 0) of a start bound, as POV-Ray reads it.
int first_pixel(double v, int size) {
  return v >= 0.0 && v < 1.0 ? truncated(double(size) * v) : truncated(v) - 1;
}

// The last pixel (from 0) of an end bound: 1.0 is a fraction here, the whole size.
int last_pixel(double v, int size) {
  return v >= 0.0 && v <= 1.0 ? truncated(double(size) * v) - 1 : truncated(v - 1.0);
}

[[noreturn]] void outside(const PartialBound& bound, const char* which, int size,
                          const char* unit) {
  throw UsageError(bound.what + ": the " + which + " " + short_number(bound.value) +
                   " is outside the picture: give a " + unit + " number from 1 to " +
                   std::to_string(size) + ", or a fraction of the picture from 0.0 to 1.0");
}

// Pixels [first, last] of one axis; the defaults are the whole axis.
struct Span {
  int first, last;
};

Span span(const std::optional<PartialBound>& start, const std::optional<PartialBound>& end,
          int size, const char* unit, const char* start_name, const char* end_name) {
  Span s{0, size - 1};
  if (start) {
    s.first = first_pixel(start->value, size);
    if (s.first < 0 || s.first >= size) outside(*start, start_name, size, unit);
  }
  if (end) {
    s.last = last_pixel(end->value, size);
    if (s.last < 0 || s.last >= size) outside(*end, end_name, size, unit);
  }
  return s;
}

}  // namespace

std::optional<render::PixelWindow> partial_window(const PartialImage& p, int width, int height) {
  if (!p.given()) return std::nullopt;
  const Span columns =
      span(p.start_column, p.end_column, width, "column", "start column", "end column");
  const Span rows = span(p.start_row, p.end_row, height, "row", "start row", "end row");
  return render::PixelWindow{columns.first, rows.first, columns.last + 1, rows.last + 1};
}

}  // namespace convray::app
