#pragma once
// POV-Ray's image_map: a picture wrapped onto space by one of its projections (map_type),
// each point's colour read from the pixel it falls on, or interpolated between pixels.
//
// Measured against the povray binary (`function { pigment { image_map {...} } }` at chosen
// points, a 4 x 2 PNG of distinct colours):
//   planar (0)       u = x, v = y: the picture covers the unit square of the x-y plane, its
//                    top row at y = 1, and repeats (once: only that square)
//   spherical (1)    u = atan2(z, x) / 2 pi (0 along +x, 1/4 along +z), v = 1/2 + latitude / pi
//   cylindrical (2)  u as spherical, v = y
//   torus (5)        u as spherical about y; v = 1/2 + the angle about the ring of radius 1
//                    over 2 pi, the angle 0 on the outside, a quarter turn at the top
//   pixel            column floor(u w), row floor((1 - v) h) (u, v wrapped into [0, 1))
//   interpolate 2    bilinear between the four nearest pixel centres, wrapping at the edges
//   interpolate 4    the four nearest pixel centres weighted by 1 / distance^2 ("normalized
//                    distance"; at a centre, that pixel)
//   once             outside [0, 1) x [0, 1): white, fully transmitting (nothing)
//   colours          8 and 16 bit files are sRGB-decoded to linear light (with assumed_gamma
//                    1); an alpha channel becomes transmit = 1 - alpha
#include <memory>
#include <vector>

#include "scene/color.hpp"

namespace convray::scene {

// The picture, as colours in the scene's working space, rows top first.
struct Image {
  int width = 0, height = 0;
  std::vector<Color> pixels;
  const Color& at(int column, int row) const { return pixels[size_t(row) * size_t(width) + size_t(column)]; }
};

enum class ImageProjection { planar = 0, spherical = 1, cylindrical = 2, torus = 5 };
enum class ImageInterpolation { none = 0, bilinear = 2, normalized_distance = 4 };

struct ImageMap {
  std::shared_ptr<const Image> image;
  ImageProjection projection = ImageProjection::planar;
  ImageInterpolation interpolation = ImageInterpolation::none;
  bool once = false;
};

}  // namespace convray::scene
