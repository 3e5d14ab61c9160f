#pragma once
// Evaluating a pigment at a point: a solid colour, checker blocks, or a pattern's value mapped
// through a colour map (the scene's, or the pattern's default as POV-Ray 3.7 has it).
//
// Default maps, measured from POV-Ray 3.7 renders of each pattern with and without a
// black-to-white map (value -> colour pairs over 10,800 pixels):
//   most patterns  black (0) to white (1)
//   marble         <0.9,0.8,0.8> at 0 to <0.9,0.08,0.08> at 0.9, then black
//   wood           <0.666,0.312,0.2> up to 0.6, then <0.4,0.133,0.066>
//   agate          white at 0 to <0.95,0.75,0.5> at 0.5; <0.9,0.7,0.5> to <0.9,0.7,0.4> at 0.6;
//                  <1,0.7,0.4> to <0.6,0.3,0> at 1
//   bozo           white below 0.4, green to 0.6, blue to 0.8, red above
//   radial         <0,1,1> at 0, <1,1,0> at 1/3, <1,0,1> at 2/3, <0,1,1> at 1
//   checker        blue, green (one colour given: it, then green); brick and hexagon: see
//                  scene::default_block_colors
#include <vector>

#include "scene/color.hpp"
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// The colour at `value` of a map whose entries ascend: below the first entry the first
// colour, above the last the last, between two entries the linear mix of their colours (all
// five channels); where two entries share a value the colour jumps there. An empty map gives
// black.
scene::Color lookup_color_map(const std::vector<scene::ColorMapEntry>& map, double value);

// The map a pattern uses when the scene gives none.
const std::vector<scene::ColorMapEntry>& default_color_map(scene::Pattern pattern);

// The pigment's colour at a world point.
scene::Color evaluate_pigment(const scene::Pigment& pigment, const Vec3& world_point);

}  // namespace convray::render
