#include "render/image_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace convray::render {

using scene::Color;
using scene::ImageProjection;

namespace {

double fract(double v) { return v - std::floor(v); }

// The turn about the y axis, 0 along +x and 1/4 along +z, in [0, 1).
double turn_about_y(const Vec3& q) { return fract(std::atan2(q.z, q.x) / (2.0 * kPi)); }

struct UV {
  double u, v;
};

UV projected(ImageProjection projection, const Vec3& q) {
  switch (projection) {
    case ImageProjection::spherical: {
      const double r = glm::length(q);
      const double latitude = r > 0.0 ? std::asin(std::clamp(q.y / r, -1.0, 1.0)) : 0.0;
      return {turn_about_y(q), 0.5 + latitude / kPi};
    }
    case ImageProjection::cylindrical:
      return {turn_about_y(q), q.y};
    case ImageProjection::torus: {
      const double around_ring = std::atan2(q.y, std::hypot(q.x, q.z) - 1.0);
      return {turn_about_y(q), fract(0.5 + around_ring / (2.0 * kPi))};
    }
    case ImageProjection::planar:
      break;
  }
  return {q.x, q.y};
}

int wrapped_index(double i, int size) {
  const double m = i - size * std::floor(i / size);
  return std::min(int(m), size - 1);
}

// Between the four pixel centres around (x, y) in pixel units (centres at half-integers).
Color interpolated(const scene::Image& image, double x, double y, bool bilinear) {
  const double fx = x - 0.5, fy = y - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const double tx = fx - x0, ty = fy - y0;
  std::array<double, 4> weight;
  if (bilinear) {
    weight = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
  } else {
    // Normalized distance: 1 / d^2 to each centre; at a centre, that pixel alone.
    const std::array<double, 4> d2 = {tx * tx + ty * ty, (1 - tx) * (1 - tx) + ty * ty,
                                      tx * tx + (1 - ty) * (1 - ty),
                                      (1 - tx) * (1 - tx) + (1 - ty) * (1 - ty)};
    double total = 0.0;
    for (int k = 0; k < 4; ++k) {
      if (d2[k] == 0.0) {
        weight = {0, 0, 0, 0};
        weight[size_t(k)] = 1.0;
        total = 1.0;
        break;
      }
      weight[size_t(k)] = 1.0 / d2[k];
      total += weight[size_t(k)];
    }
    for (double& w : weight) w /= total;
  }
  Color sum{Vec3(0.0), 0.0, 0.0};
  for (int k = 0; k < 4; ++k) {
    const int column = wrapped_index(x0 + (k & 1), image.width);
    const int row = wrapped_index(y0 + (k >> 1), image.height);
    sum = sum + weight[size_t(k)] * image.at(column, row);
  }
  return sum;
}

}  // namespace

Color image_map_color(const scene::ImageMap& map, const Vec3& q) {
  const scene::Image& image = *map.image;
  UV uv = projected(map.projection, q);
  if (map.once && !(uv.u >= 0.0 && uv.u < 1.0 && uv.v >= 0.0 && uv.v < 1.0)) {
    return Color{Vec3(1.0), 0.0, 1.0};
  }
  uv = {fract(uv.u), fract(uv.v)};
  const double x = uv.u * image.width;
  const double y = (1.0 - uv.v) * image.height;
  switch (map.interpolation) {
    case scene::ImageInterpolation::bilinear:
      return interpolated(image, x, y, true);
    case scene::ImageInterpolation::normalized_distance:
      return interpolated(image, x, y, false);
    case scene::ImageInterpolation::none:
      break;
  }
  return image.at(wrapped_index(std::floor(x), image.width),
                  wrapped_index(std::floor(y), image.height));
}

}  // namespace convray::render
