#pragma once
// POV-Ray's block patterns besides checker: each point lies in one block, and the block's
// number (0, 1 or 2) picks the colour, pigment, normal or texture listed in that place.
//
// Measured against the povray binary (`function { pigment { ... } }` evaluated at 400 random
// points per setting, every one alike, for three brick sizes and mortars and for hexagon):
//   brick    courses of height size.y along y; course k = floor(y / size.y). Odd courses are
//            shifted by half a brick along x, even ones by half a brick along z. In a cell the
//            last `mortar` of each axis is mortar (block 0), the rest brick (block 1):
//            mortar where fmod(x', size.x) >= size.x - mortar, and alike for y and z'.
//            Every coordinate is first moved by 1e-10, as POV-Ray does (block_patterns.cpp).
//   hexagon  regular hexagons of circumradius 1 in the x-z plane (any y), corners on the
//            x axis, one centred at the origin; centre (1.5 a, sqrt(3) (b + a / 2)) has block
//            (b - a) mod 3, so that no two neighbours share one.
#include "util/math.hpp"

namespace convray::render {

// POV-Ray's default brick: 8 x 3 x 4.5 with mortar 0.5.
int brick_block(const Vec3& pattern_point, const Vec3& brick_size, double mortar);

int hexagon_block(const Vec3& pattern_point);

}  // namespace convray::render
