#include "implicit/inside_balls.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/coherent_rays.hpp"

namespace convray::implicit {
namespace {

// How far inside the supports' box the segment's far end may lie, relative to the size of
// the coordinates, for the field there to count as 0 < T: the clip to the box (ImplicitShape)
// leaves it there to a few ulps. Every support holding a point within d of its box's face
// lies within d of that face (the box holds the support's box), so the point is farther than
// R - d from the skeleton, where the kernel is below (2 d / R)^2 of its peak: 4e-18 of it for
// a box 1000 radii across.
constexpr double kFarEndDepth = 1e-9;

struct Ball {
  const ConvolutionSurface::Impl* surface = nullptr;
  uint64_t serial = 0;  // the surface's (addresses are reused)
  uint64_t run = 0;
  Vec3 center{0.0};
  double radius = 0.0;
};
// A few surfaces' balls per thread: a tile's shadow rays meet one or two surfaces.
thread_local std::array<Ball, 4> balls;
thread_local unsigned next_slot = 0;

// Whether a blocked shadow ray's search should look for a ball: each look costs a few samples
// with the gradient, paid back only where the balls are wide beside the spacing of the rays
// (the soup of scenes/soup.pov: most of its blocked rays settled; the dragon at R = 1, whose
// balls are a tenth of a pixel's footprint, none, and 5 % more time with every search
// looking). So each thread keeps per surface how many searches looked and how many rays
// the balls settled, and looks while the balls settle at least one ray per two looks, after
// kWarmUp looks, and every kRetry-th search otherwise (the rays' spacing changes across a
// picture).
constexpr uint64_t kWarmUp = 16;
constexpr uint64_t kRetry = 16;
struct Usage {
  const ConvolutionSurface::Impl* surface = nullptr;
  uint64_t serial = 0;
  uint64_t searches = 0, looks = 0, settled = 0;
};
thread_local std::array<Usage, 4> usage;
thread_local unsigned next_usage = 0;

Usage& usage_of(const ConvolutionSurface::Impl& surface) {
  for (Usage& u : usage) {
    if (u.surface == &surface && u.serial == surface.serial) return u;
  }
  Usage& u = usage[next_usage++ % usage.size()];
  u = {&surface, surface.serial};
  return u;
}

bool current(const Ball& b, const ConvolutionSurface::Impl& surface) {
  return b.surface == &surface && b.serial == surface.serial && b.run == coherent_run();
}

// Whether p lies on the outside of the supports' box, to rounding (kFarEndDepth).
bool on_bounding_box(const ConvolutionSurface::Impl& surface, const Vec3& p) {
  const Box3 box = surface.index->bounds();
  double depth = kInfinity, scale = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    depth = std::min({depth, p[axis] - box.lo[axis], box.hi[axis] - p[axis]});
    scale = std::max({scale, std::abs(p[axis]), box.hi[axis] - box.lo[axis]});
  }
  return depth <= kFarEndDepth * scale;
}

}  // namespace

double inside_radius(double value, double threshold, double slope, double bend) {
  // The sums' rounding, generously: a relative 1e-12 of the value.
  const double margin = value - threshold - 1e-12 * std::abs(value);
  if (!(margin > 0.0) || !(bend > 0.0) || !(slope >= 0.0)) return 0.0;
  // The positive root of bend d^2 / 2 + slope d - margin, written so nothing cancels.
  const double radius = 2.0 * margin / (slope + std::sqrt(slope * slope + 2.0 * bend * margin));
  return std::isfinite(radius) ? radius * (1.0 - 1e-9) : 0.0;
}

bool InsideBalls::settle(const ConvolutionSurface::Impl& surface, const Ray& ray, double tmin,
                         double tmax) {
  const Vec3& d = ray.direction;
  const double dd = glm::dot(d, d);
  if (!(tmin <= tmax) || !(dd > 0.0)) return false;
  bool any = false;
  for (const Ball& b : balls) any = any || current(b, surface);
  if (!any || !on_bounding_box(surface, ray.at(tmax))) return false;
  for (const Ball& b : balls) {
    if (!current(b, surface)) continue;
    const Vec3 w = b.center - ray.origin;
    const double t = std::clamp(glm::dot(w, d) / dd, tmin, tmax);
    const Vec3 gap = ray.at(t) - b.center;
    if (glm::dot(gap, gap) < b.radius * b.radius) {
      ++usage_of(surface).settled;
      return true;
    }
  }
  return false;
}

bool InsideBalls::worth_looking(const ConvolutionSurface::Impl& surface) {
  if (!surface.nonnegative) return false;
  const Usage& u = usage_of(surface);
  return u.looks < kWarmUp || 2 * u.settled >= u.looks || u.searches % kRetry == 0;
}

void InsideBalls::remember(const ConvolutionSurface::Impl& surface, const InsideBall* ball) {
  Usage& u = usage_of(surface);
  ++u.searches;
  u.looks += ball != nullptr;
  if (!ball || !(ball->radius > 0.0)) return;
  // The most recent in the oldest slot: the next rays pass nearest it.
  balls[next_slot++ % balls.size()] = {&surface, surface.serial, coherent_run(), ball->center,
                                       ball->radius};
}

}  // namespace convray::implicit
