#pragma once
// An image_map's colour at a point of its pattern space (the projections, pixel rules and
// interpolations measured against POV-Ray: scene/image_map.hpp).
#include "scene/image_map.hpp"
#include "util/math.hpp"

namespace convray::render {

scene::Color image_map_color(const scene::ImageMap& map, const Vec3& pattern_point);

}  // namespace convray::render
