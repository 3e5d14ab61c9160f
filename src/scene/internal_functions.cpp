// POV-Ray's internal functions (functions.inc: `#declare f_r = function { internal(57) }`)
// that convray has, from the reference manual's descriptions of them. The others are refused
// where a scene calls them (sdl/function_compiler.cpp).
#include <algorithm>
#include <cmath>

#include "scene/function.hpp"

namespace convray::scene {

namespace {

double length3(double x, double y, double z) { return std::sqrt(x * x + y * y + z * z); }

// f_rounded_box: a box of half sizes (sx, sy, sz) whose edges and corners are rounded with
// radius r: the distance to the box shrunk by r, minus r (negative inside).
double rounded_box(std::span<const double> a) {
  const double r = a[3];
  const double qx = std::abs(a[0]) - (a[4] - r);
  const double qy = std::abs(a[1]) - (a[5] - r);
  const double qz = std::abs(a[2]) - (a[6] - r);
  const double outside = length3(std::max(qx, 0.0), std::max(qy, 0.0), std::max(qz, 0.0));
  const double inside = std::min(std::max({qx, qy, qz}), 0.0);
  return outside + inside - r;
}

}  // namespace

bool internal_function_of(int pov_number, InternalFunction& out) {
  switch (pov_number) {
    case 57:
      out = InternalFunction::r;
      return true;
    case 60:
      out = InternalFunction::rounded_box;
      return true;
    case 61:
      out = InternalFunction::sphere;
      return true;
    case 70:
      out = InternalFunction::torus;
      return true;
    default:
      return false;
  }
}

int internal_function_arity(InternalFunction f) {
  switch (f) {
    case InternalFunction::r:
      return 3;
    case InternalFunction::sphere:
      return 4;
    case InternalFunction::torus:
      return 5;
    case InternalFunction::rounded_box:
      return 7;
  }
  return 3;
}

double evaluate_internal(InternalFunction f, std::span<const double> a) {
  switch (f) {
    case InternalFunction::r:
      return length3(a[0], a[1], a[2]);
    case InternalFunction::sphere:
      return length3(a[0], a[1], a[2]) - a[3];
    case InternalFunction::torus: {
      // A torus about the y axis, as POV-Ray's torus object: major radius a[3], minor a[4].
      const double ring = std::hypot(a[0], a[2]) - a[3];
      return std::hypot(ring, a[1]) - a[4];
    }
    case InternalFunction::rounded_box:
      return rounded_box(a);
  }
  return 0.0;
}

}  // namespace convray::scene
