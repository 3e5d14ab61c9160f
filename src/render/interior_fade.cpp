#include "render/interior_fade.hpp"

#include <cmath>

namespace convray::render {

namespace {

// POV-Ray switches from its rational fall-off to the exponential one at this power.
constexpr double kExponentialFadePower = 1000.0;

}  // namespace

Vec3 interior_fade(const scene::Interior& interior, double distance) {
  if (!fades(interior)) return Vec3(1.0);
  const double depth = distance / interior.fade_distance;
  const double kept = interior.fade_power >= kExponentialFadePower
                          ? std::exp(-depth)
                          : 1.0 / (1.0 + std::pow(depth, interior.fade_power));
  return Vec3(kept) + (1.0 - kept) * interior.fade_color;
}

}  // namespace convray::render
