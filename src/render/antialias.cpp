#include "render/antialias.hpp"

#include <algorithm>
#include <cmath>

#include "render/sample_hash.hpp"

namespace convray::render {

double color_distance(const Vec3& a, const Vec3& b, double gamma) {
  const double exponent = gamma > 0.0 ? 1.0 / gamma : 1.0;
  auto encoded = [exponent](const Vec3& c) {
    return glm::pow(glm::clamp(c, 0.0, 1.0), Vec3(exponent));
  };
  const Vec3 d = glm::abs(encoded(a) - encoded(b));
  return d.r + d.g + d.b;
}

std::vector<uint8_t> pixels_to_supersample(const Film& film, double threshold, double gamma) {
  const int w = film.width(), h = film.height();
  std::vector<uint8_t> flags(size_t(w) * size_t(h), 0);
  auto flag = [&](int i, int j) { flags[size_t(j) * size_t(w) + size_t(i)] = 1; };
  // Each pair of neighbours once: with the right one and with the one below.
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const Vec3 here = film.at(i, j);
      if (i + 1 < w && color_distance(here, film.at(i + 1, j), gamma) > threshold) {
        flag(i, j);
        flag(i + 1, j);
      }
      if (j + 1 < h && color_distance(here, film.at(i, j + 1), gamma) > threshold) {
        flag(i, j);
        flag(i, j + 1);
      }
    }
  }
  return flags;
}

std::vector<Vec2> supersample_positions(int i, int j, const AntialiasSettings& settings) {
  const int n = std::max(settings.depth, 1);
  const double cell = 1.0 / n;
  const double amount = settings.jitter ? std::clamp(settings.jitter_amount, 0.0, 1.0) : 0.0;
  const uint64_t pixel = hash_values(settings.seed, uint64_t(uint32_t(i)), uint64_t(uint32_t(j)));
  std::vector<Vec2> positions;
  positions.reserve(size_t(n) * size_t(n));
  for (int b = 0; b < n; ++b) {
    for (int a = 0; a < n; ++a) {
      Vec2 offset(0.0);
      if (amount > 0.0) {
        const uint64_t sample = uint64_t(b) * uint64_t(n) + uint64_t(a);
        offset.x = amount * (unit_from_hash(hash_values(pixel, sample, 1)) - 0.5);
        offset.y = amount * (unit_from_hash(hash_values(pixel, sample, 2)) - 0.5);
      }
      positions.emplace_back(i + (a + 0.5 + offset.x) * cell, j + (b + 0.5 + offset.y) * cell);
    }
  }
  return positions;
}

}  // namespace convray::render
