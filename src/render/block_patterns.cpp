#include "render/block_patterns.hpp"

#include <cmath>

namespace convray::render {

namespace {

// POV-Ray moves every point by this much along each axis before finding its brick (measured
// by bisection with the povray binary: the boundaries at x = 7.5, 8, 15.5, 79.5 and
// y = 2.5, 3, 29.5 of the default brick all lie 1e-10 below where they would be, to 1e-15).
// A face lying on a mortar boundary (a box scaled to it) then shows mortar or brick
// consistently instead of flickering with the rounding of its hit points.
constexpr double kBrickTolerance = 1e-10;

// v modulo a positive period, in [0, period).
double wrapped(double v, double period) { return v - period * std::floor(v / period); }

}  // namespace

int brick_block(const Vec3& pattern_point, const Vec3& size, double mortar) {
  const Vec3 q = pattern_point + Vec3(kBrickTolerance);
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
