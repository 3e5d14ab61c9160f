// Colour maps whose values do not ascend, made ascending without changing a single colour
// POV-Ray would pick from them (see ascending_equivalent in item_parsers.hpp).
#include <algorithm>

#include "sdl/item_parsers.hpp"

namespace convray::sdl::items {

namespace {

bool ascending(const ColorMap& map) {
  return std::is_sorted(map.begin(), map.end(),
                        [](const auto& a, const auto& b) { return a.value < b.value; });
}

// The colour an ascending map gives just below v (v inside its range).
scene::Color color_below(const ColorMap& map, double v) {
  for (size_t k = 1; k < map.size(); ++k) {
    if (map[k].value < v) continue;
    const scene::ColorMapEntry& a = map[k - 1];
    const scene::ColorMapEntry& b = map[k];
    if (b.value == a.value) return b.color;
    return scene::mix(a.color, b.color, (v - a.value) / (b.value - a.value));
  }
  return map.back().color;
}

}  // namespace

ColorMap ascending_equivalent(const ColorMap& map) {
  if (map.size() < 2 || ascending(map)) return map;
  // Between the highest value seen before entry j (reach) and entry j's own value, the scan
  // stops at j and blends with entry j - 1, even when j - 1 stepped back below reach.
  ColorMap result{map.front()};
  double reach = map.front().value;
  for (size_t j = 1; j < map.size(); ++j) {
    const scene::ColorMapEntry& a = map[j - 1];
    const scene::ColorMapEntry& b = map[j];
    if (b.value <= reach) continue;  // an entry at or above it always stops the scan first
    if (a.value < reach) {
      const double w = (reach - a.value) / (b.value - a.value);
      result.push_back({reach, scene::mix(a.color, b.color, w)});
    }
    result.push_back(b);
    reach = b.value;
  }
  // At and above the last entry's value its colour holds, even below values written earlier.
  const scene::ColorMapEntry& last = map.back();
  if (last.value < reach) {
    const scene::Color below = color_below(result, last.value);
    std::erase_if(result, [&](const auto& entry) { return entry.value >= last.value; });
    result.push_back({last.value, below});
    result.push_back(last);
  }
  return result;
}

}  // namespace convray::sdl::items
