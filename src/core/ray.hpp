#pragma once
// Rays and what they hit: the vocabulary shared by the surface finders and the renderer.
#include "util/math.hpp"

namespace convray {

// origin + t * direction; direction has unit length, so t is a distance.
struct Ray {
  Vec3 origin{0.0};
  Vec3 direction{0.0, 0.0, 1.0};

  Vec3 at(double t) const { return origin + t * direction; }
};

// The first crossing of a surface: its distance along the ray, the point, and the unit normal
// pointing out of the solid (towards decreasing field for convolution surfaces).
struct SurfaceHit {
  double t = 0.0;
  Vec3 point{0.0};
  Vec3 normal{0.0, 0.0, 1.0};
};

}  // namespace convray
