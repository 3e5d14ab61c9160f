#pragma once
// POV-Ray's colour: linear RGB plus `filter` (light passing through, tinted by the colour) and
// `transmit` (light passing through untinted). Values are as the scene wrote them after
// POV-Ray 3.7's gamma rules (`srgb` keywords decoded to linear by the parser).
#include "util/math.hpp"

namespace convray::scene {

struct Color {
  Vec3 rgb{0.0};
  double filter = 0.0;
  double transmit = 0.0;

  bool opaque() const { return filter == 0.0 && transmit == 0.0; }
};

inline Color operator*(double s, const Color& c) {
  return {s * c.rgb, s * c.filter, s * c.transmit};
}
inline Color operator+(const Color& a, const Color& b) {
  return {a.rgb + b.rgb, a.filter + b.filter, a.transmit + b.transmit};
}
// Linear interpolation of every channel: (1 - w) a + w b.
inline Color mix(const Color& a, const Color& b, double w) { return (1.0 - w) * a + w * b; }

}  // namespace convray::scene
