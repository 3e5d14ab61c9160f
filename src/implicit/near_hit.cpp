#include "implicit/near_hit.hpp"

#include <array>
#include <cmath>

#include "core/coherent_rays.hpp"

namespace convray::implicit {

double field_bound_near(const NearHit& hit, const Vec3& x, double bend_at_x) {
  const Vec3 step = x - hit.point;
  const double linear = glm::dot(hit.gradient, step);
  const double quadratic = 0.5 * (hit.bend + bend_at_x) * glm::dot(step, step);
  // The sums behind the sample and the products here round to a few ulps of their terms'
  // magnitudes: a relative 1e-12 of each covers them many times over.
  const double rounding = 1e-12 * (std::abs(hit.value) + std::abs(linear) + quadratic);
  return hit.value + linear + quadratic + rounding;
}

namespace {

struct Slot {
  const ConvolutionSurface::Impl* surface = nullptr;
  uint64_t serial = 0;  // the surface's (addresses are reused)
  uint64_t run = 0;
  NearHit hit;
};
// A scene's camera rays meet a few surfaces one after the other.
thread_local std::array<Slot, 4> slots;
thread_local unsigned next_slot = 0;

}  // namespace

const NearHit* NearHits::find(const ConvolutionSurface::Impl& surface) {
  for (const Slot& s : slots) {
    if (s.surface == &surface && s.serial == surface.serial && s.run == coherent_run()) {
      return &s.hit;
    }
  }
  return nullptr;
}

void NearHits::remember(const ConvolutionSurface::Impl& surface, const NearHit& hit) {
  Slot* slot = nullptr;
  for (Slot& s : slots) {
    if (s.surface == &surface && s.serial == surface.serial) slot = &s;
  }
  if (!slot) slot = &slots[next_slot++ % slots.size()];
  *slot = {&surface, surface.serial, coherent_run(), hit};
}

}  // namespace convray::implicit
