#include "render/layer_blend.hpp"

#include <algorithm>

namespace convray::render {

LayerBlend layer_blend(const scene::Color& c, Layer layer, double language_version) {
  const double f = c.filter, t = c.transmit;
  constexpr double kSlack = 1e-9;  // versions are written with two digits
  if (language_version >= 3.7 - kSlack) return {1.0 - f - t, f * c.rgb + Vec3(t)};
  const bool before_3_5 = language_version < 3.5 - kSlack;
  if (layer == Layer::sky || (layer == Layer::over_layer && before_3_5)) {
    return {1.0 - f - t, Vec3(f + t)};
  }
  const double brightest = std::max({c.rgb.r, c.rgb.g, c.rgb.b});
  return {1.0 - f * brightest - t, f * c.rgb + Vec3(t)};
}

}  // namespace convray::render
