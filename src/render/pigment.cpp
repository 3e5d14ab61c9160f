#include "render/pigment.hpp"

#include <algorithm>

#include "render/image_map.hpp"
#include "render/noise.hpp"
#include "render/patterns.hpp"
#include "render/warps.hpp"

namespace convray::render {

using scene::Color;
using scene::ColorMapEntry;
using scene::Pattern;

namespace {

Color rgb(double r, double g, double b) { return Color{Vec3(r, g, b), 0.0, 0.0}; }

const std::vector<ColorMapEntry> kGreyRamp = {{0.0, rgb(0, 0, 0)}, {1.0, rgb(1, 1, 1)}};

const std::vector<ColorMapEntry> kMarbleMap = {{0.0, rgb(0.9, 0.8, 0.8)},
                                               {0.9, rgb(0.9, 0.08, 0.08)},
                                               {0.9, rgb(0, 0, 0)},
                                               {1.0, rgb(0, 0, 0)}};

const std::vector<ColorMapEntry> kWoodMap = {{0.0, rgb(0.666, 0.312, 0.2)},
                                             {0.6, rgb(0.666, 0.312, 0.2)},
                                             {0.6, rgb(0.4, 0.133, 0.066)},
                                             {1.0, rgb(0.4, 0.133, 0.066)}};

const std::vector<ColorMapEntry> kAgateMap = {
    {0.0, rgb(1, 1, 1)},       {0.5, rgb(0.95, 0.75, 0.5)}, {0.5, rgb(0.9, 0.7, 0.5)},
    {0.6, rgb(0.9, 0.7, 0.4)}, {0.6, rgb(1.0, 0.7, 0.4)},   {1.0, rgb(0.6, 0.3, 0.0)}};

const std::vector<ColorMapEntry> kBozoMap = {
    {0.0, rgb(1, 1, 1)}, {0.4, rgb(1, 1, 1)}, {0.4, rgb(0, 1, 0)}, {0.6, rgb(0, 1, 0)},
    {0.6, rgb(0, 0, 1)}, {0.8, rgb(0, 0, 1)}, {0.8, rgb(1, 0, 0)}, {1.0, rgb(1, 0, 0)}};

const std::vector<ColorMapEntry> kRadialMap = {
    {0.0, rgb(0, 1, 1)}, {1.0 / 3.0, rgb(1, 1, 0)}, {2.0 / 3.0, rgb(1, 0, 1)}, {1.0, rgb(0, 1, 1)}};

// mandel's own map, read from the povray binary (`function { pigment { mandel 1000 } }` at
// points of every escape count k = 0..150): black up to 0.001, then cyan, yellow at 0.012,
// magenta at 0.015, cyan from 0.1 on (the set itself, value 1, is cyan).
const std::vector<ColorMapEntry> kMandelMap = {{0.001, rgb(0, 0, 0)},
                                               {0.001, rgb(0, 1, 1)},
                                               {0.012, rgb(1, 1, 0)},
                                               {0.015, rgb(1, 0, 1)},
                                               {0.1, rgb(0, 1, 1)}};

Color block_color(const scene::Pigment& pigment, const Vec3& world_point) {
  const size_t block = size_t(pattern_value(pigment.space, world_point));
  if (block < pigment.block_colors.size()) return pigment.block_colors[block];
  return scene::default_block_colors(pigment.space.pattern)[block];
}

}  // namespace

Color lookup_color_map(const std::vector<ColorMapEntry>& map, double value) {
  if (map.empty()) return Color{};
  if (value <= map.front().value) return map.front().color;
  if (value >= map.back().value) return map.back().color;
  // The first entry above the value; its predecessor is at or below it.
  const auto above =
      std::upper_bound(map.begin(), map.end(), value,
                       [](double v, const ColorMapEntry& entry) { return v < entry.value; });
  const ColorMapEntry& low = *(above - 1);
  const ColorMapEntry& high = *above;
  const double span = high.value - low.value;
  if (!(span > 0.0)) return high.color;
  return scene::mix(low.color, high.color, (value - low.value) / span);
}

const std::vector<ColorMapEntry>& default_color_map(Pattern pattern) {
  switch (pattern) {
    case Pattern::marble:
      return kMarbleMap;
    case Pattern::wood:
      return kWoodMap;
    case Pattern::agate:
      return kAgateMap;
    case Pattern::bozo:
      return kBozoMap;
    case Pattern::radial:
      return kRadialMap;
    case Pattern::mandel:
      return kMandelMap;
    default:
      return kGreyRamp;
  }
}

namespace {

// Where an image_map is read: its space's point, moved by the plain turbulence as any
// pattern's is (render/patterns.cpp).
Vec3 image_map_point(const scene::PatternSpace& space, const Vec3& world_point) {
  Vec3 q = pattern_point(space, world_point);
  const scene::Turbulence& t = space.turbulence;
  if (t.active()) q += t.amount * turbulence_vector(q, t.octaves, t.omega, t.lambda);
  return q;
}

// The pigments of a pigment_map at `value`, as a colour map mixes its colours.
Color lookup_pigment_map(const std::vector<scene::PigmentMapEntry>& map, double value,
                         const Vec3& world_point) {
  const auto colour = [&](const scene::PigmentMapEntry& entry) {
    return evaluate_pigment(*entry.pigment, world_point);
  };
  if (value <= map.front().value) return colour(map.front());
  if (value >= map.back().value) return colour(map.back());
  const auto above =
      std::upper_bound(map.begin(), map.end(), value,
                       [](double v, const scene::PigmentMapEntry& entry) { return v < entry.value; });
  const scene::PigmentMapEntry& low = *(above - 1);
  const scene::PigmentMapEntry& high = *above;
  const double span = high.value - low.value;
  if (!(span > 0.0)) return colour(high);
  return scene::mix(colour(low), colour(high), (value - low.value) / span);
}

// An average: the pigments mixed by weight / sum of the weights (all five channels).
Color average_pigments(const std::vector<scene::PigmentMapEntry>& map, const Vec3& world_point) {
  double total = 0.0;
  for (const scene::PigmentMapEntry& entry : map) total += entry.value;
  Color sum{Vec3(0.0), 0.0, 0.0};
  if (!(total > 0.0)) return sum;
  for (const scene::PigmentMapEntry& entry : map) {
    const Color c = evaluate_pigment(*entry.pigment, world_point);
    const double w = entry.value / total;
    sum.rgb += w * c.rgb;
    sum.filter += w * c.filter;
    sum.transmit += w * c.transmit;
  }
  return sum;
}

}  // namespace

Color evaluate_pigment(const scene::Pigment& pigment, const Vec3& world_point) {
  if (pigment.space.pattern == Pattern::average) {
    return average_pigments(pigment.pigment_map, world_point);
  }
  if (!pigment.pigment_map.empty() && pigment.space.pattern != Pattern::solid) {
    return lookup_pigment_map(pigment.pigment_map, pattern_value(pigment.space, world_point),
                              world_point);
  }
  switch (pigment.space.pattern) {
    case Pattern::solid:
      return pigment.color;
    case Pattern::image_map:
      return image_map_color(*pigment.image_map, image_map_point(pigment.space, world_point));
    case Pattern::checker:
    case Pattern::brick:
    case Pattern::hexagon:
      return block_color(pigment, world_point);
    default:
      break;
  }
  const double value = pattern_value(pigment.space, world_point);
  const std::vector<ColorMapEntry>& map =
      pigment.color_map.empty() ? default_color_map(pigment.space.pattern) : pigment.color_map;
  return lookup_color_map(map, value);
}

}  // namespace convray::render
