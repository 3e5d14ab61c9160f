#include "render/film.hpp"

#include <stdexcept>

namespace convray::render {

Film::Film(int width, int height) : width_(width), height_(height) {
  if (width < 1 || height < 1) throw std::invalid_argument("a film needs at least one pixel");
  rgb_.assign(3 * size_t(width) * size_t(height), 0.0f);
}

void Film::set(int i, int j, const Vec3& rgb) {
  const size_t k = index(i, j);
  rgb_[k] = float(rgb.r);
  rgb_[k + 1] = float(rgb.g);
  rgb_[k + 2] = float(rgb.b);
}

Vec3 Film::at(int i, int j) const {
  const size_t k = index(i, j);
  return Vec3(rgb_[k], rgb_[k + 1], rgb_[k + 2]);
}

}  // namespace convray::render
