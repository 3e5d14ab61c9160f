#include "render/block_patterns.hpp"

#include <cmath>

namespace convray::render {

namespace {

// v modulo a positive period, in [0, period).
double wrapped(double v, double period) { return v - period * std::floor(v / period); }

}  // namespace

int brick_block(const Vec3& q, const Vec3& size, double mortar) {
  const bool odd_course = std::fmod(std::abs(std::floor(q.y / size.y)), 2.0) == 1.0;
  const double x = q.x + (odd_course ? 0.5 * size.x : 0.0);
  const double z = q.z + (odd_course ? 0.0 : 0.5 * size.z);
  const bool in_mortar = wrapped(x, size.x) >= size.x - mortar ||
                         wrapped(q.y, size.y) >= size.y - mortar ||
                         wrapped(z, size.z) >= size.z - mortar;
  return in_mortar ? 0 : 1;
}

int hexagon_block(const Vec3& q) {
  // The hexagons are the cells of the lattice of centres: the nearest centre's cell. Centres
  // lie in columns 1.5 apart; the nearest is in the column nearest to x or one beside it.
  const double root3 = std::sqrt(3.0);
  const double column = std::round(q.x / 1.5);
  double best = INFINITY, best_a = 0.0, best_b = 0.0;
  for (double a = column - 1.0; a <= column + 1.0; a += 1.0) {
    const double b = std::round(q.z / root3 - 0.5 * a);
    const double dx = q.x - 1.5 * a;
    const double dz = q.z - root3 * (b + 0.5 * a);
    const double d = dx * dx + dz * dz;
    if (d < best) best = d, best_a = a, best_b = b;
  }
  const double block = std::fmod(best_b - best_a, 3.0);
  return int(block < 0.0 ? block + 3.0 : block);
}

}  // namespace convray::render
