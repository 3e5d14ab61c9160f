#pragma once
// Textures as POV-Ray describes them: a pigment (a colour, or a pattern mapped through a
// colour map), a finish (how light is reflected), a normal perturbation and, for the object,
// an interior. Plain records; render/ evaluates them.
//
// Pattern space: every pattern is evaluated at `transform.inverse_point(world_point)`. The
// parser appends an object's transforms to the transforms of the textures the object already
// has (POV-Ray moves a texture with its object), so the renderer needs nothing else.
#include <memory>
#include <vector>

#include "scene/color.hpp"
#include "scene/image_map.hpp"
#include "scene/function.hpp"
#include "scene/transform.hpp"

namespace convray::scene {

enum class Pattern {
  solid,     // pigment { color ... }: no pattern
  checker,   // unit cubes alternating colour_map entries 0 and 1
  gradient,  // fractional part of p . axis
  marble,    // triangle wave of x (+ turbulence)
  wood,      // concentric cylinders about z
  granite,   // fractal noise
  agate,     // turbulence-warped sine
  bozo,      // noise
  radial,    // angle about y in [0, 1)
  onion,     // concentric spheres
  leopard,
  spotted,   // same as bozo
  ripples,   // normal patterns (also usable as pigments)
  waves,
  wrinkles,
  bumps,
  dents,
  planar,       // 1 at y = 0 falling to 0 at |y| = 1
  spherical,    // 1 at the origin falling to 0 at |p| = 1
  cylindrical,  // 1 on the y axis falling to 0 at distance 1
  boxed,        // 1 at the origin falling to 0 on the cube's faces at |x|, |y|, |z| = 1
  spiral1,      // `arms` spirals winding about z like a screw
  mandel,       // the Mandelbrot set in the x-y plane: escape time / `iterations`
  average,      // pigments only: the pigment_map's pigments mixed by their weights
  image_map,    // pigments only: a picture's colours (Pigment::image_map)
  brick,        // block pattern: mortar (block 0) and bricks (block 1) in courses along y
  hexagon,      // block pattern: hexagons in the x-z plane, blocks 0, 1 and 2
  function,     // a user function of x, y, z (PatternSpace::function), wrapped like gradient
  quilted,      // unit cubes with rounded seams shaped by control0 and control1
};

// A colour map's entries ascend in value (the parser makes them so, keeping POV-Ray's
// colours); two in a row with the same value make a sharp step.
struct ColorMapEntry {
  double value = 0.0;  // in [0, 1], ascending
  Color color;
};

// POV-Ray's turbulence warp: the pattern is evaluated at p + turbulence * noise_vector(p),
// the noise summed over `octaves` with amplitude `omega`^k and frequency `lambda`^k.
struct Turbulence {
  Vec3 amount{0.0};
  int octaves = 6;
  double omega = 0.5;
  double lambda = 2.0;
  bool active() const { return amount != Vec3(0.0); }
};

// POV-Ray's `warp { ... }`: a change of the pattern-space point that sits between the
// transforms listed before it and those after it, where the scene lists it.
//   turbulence  p + amount * (the turbulence vector at p), as the `turbulence` modifier
//   repeat      the slab 0 <= p[axis] < width copied along the axis: copy k = floor(p[axis] /
//               width) is moved back k widths, flipped on the `flip` axes when k is odd
//               (p[axis] -> width - p[axis], the others negated), then moved by k * offset
//               (measured with the povray binary: tests/render/povray_warp_test.cpp)
struct Warp {
  enum class Kind { turbulence, repeat };
  Kind kind = Kind::turbulence;
  Turbulence turbulence;  // turbulence
  int axis = 0;           // repeat: 0, 1 or 2
  double width = 1.0;     // repeat: > 0
  Vec3 offset{0.0};       // repeat
  Vec3 flip{0.0};         // repeat: nonzero components flip
  Transform inner;        // the transforms listed before this warp (after the previous one)
};

// POV-Ray's wave types: how a pattern's value v = value * frequency + phase becomes the
// value looked up in the map. `pattern_default`: triangle for marble, wood and spiral1, ramp otherwise.
enum class Wave { pattern_default, ramp, triangle, sine, scallop, cubic, poly };

// What every pattern shares: where it is evaluated and how its value is reshaped.
struct PatternSpace {
  Pattern pattern = Pattern::solid;
  Vec3 gradient_axis{1.0, 0.0, 0.0};  // gradient only
  double arms = 1.0;                  // spiral1 only: its number of arms
  int iterations = 0;                 // mandel only: the most iterations
  Vec3 brick_size{8.0, 3.0, 4.5};     // brick only: one brick with its mortar
  double mortar = 0.5;                // brick only: the mortar's width
  double agate_turb = 1.0;            // agate only: the weight of its turbulence
  double control0 = 1.0;              // quilted only: the seam's two cubic controls; both
  double control1 = 1.0;              // 1 by default (measured with the povray binary)
  int noise_generator = 2;            // POV-Ray's noise generator: 1 original, 2 range-corrected
  std::shared_ptr<const Function> function;  // function only
  Turbulence turbulence;
  double frequency = 1.0;  // value -> fract(value * frequency + phase)
  double phase = 0.0;
  Wave wave = Wave::pattern_default;
  double wave_exponent = 1.0;  // poly_wave's
  // Listed warps, innermost (first listed) first; each carries the transforms listed before
  // it. `transform` is then what was listed after the last warp (and the object's moves).
  std::vector<Warp> warps;
  Transform transform;     // pattern space -> world (without warps: all the transforms)
};

// Checker, brick and hexagon: the value is a block number that picks a listed colour.
inline bool is_block_pattern(Pattern pattern) {
  return pattern == Pattern::checker || pattern == Pattern::brick || pattern == Pattern::hexagon;
}

// How many colours (pigments, textures) a block pattern lists: 2, or 3 for hexagon.
inline int block_count(Pattern pattern) { return pattern == Pattern::hexagon ? 3 : 2; }

// The colours of a block pattern whose scene lists fewer (measured with the povray binary):
// checker blue, green; brick mortar grey 0.5, brick <0.6, 0.15, 0.15>; hexagon blue, green,
// red.
inline std::vector<Color> default_block_colors(Pattern pattern) {
  switch (pattern) {
    case Pattern::brick:
      return {{Vec3(0.5)}, {Vec3(0.6, 0.15, 0.15)}};
    case Pattern::hexagon:
      return {{Vec3(0, 0, 1)}, {Vec3(0, 1, 0)}, {Vec3(1, 0, 0)}};
    default:
      return {{Vec3(0, 0, 1)}, {Vec3(0, 1, 0)}};
  }
}

struct Pigment;

// A `pigment_map` entry: at this pattern value, this whole pigment.
struct PigmentMapEntry {
  double value = 0.0;  // ascending
  std::shared_ptr<const Pigment> pigment;
};

struct Pigment {
  PatternSpace space;
  Color color;                          // solid; also the colour where no map applies
  std::vector<ColorMapEntry> color_map; // empty: the pattern's default map (render/)
  // checker, brick and hexagon: the listed colours, in order.
  std::vector<Color> block_colors;
  // Set: the pattern's value picks (between two entries: mixes) whole pigments instead of
  // colours; color_map is not used. For `average` the values are the pigments' weights.
  std::vector<PigmentMapEntry> pigment_map;
  // image_map only: the picture and how it is wrapped.
  std::shared_ptr<const ImageMap> image_map;
};

struct Finish {
  Vec3 ambient{0.1};     // POV-Ray 3.7 default, multiplied by global ambient_light
  double diffuse = 0.6;
  double brilliance = 1.0;
  double phong = 0.0;
  double phong_size = 40.0;
  double specular = 0.0;
  double roughness = 0.05;
  Vec3 reflection{0.0};  // reflection colour; with variable_reflection its maximum
  // Variable reflection (render/variable_reflection.hpp): from reflection_min facing the
  // viewer to reflection at grazing angles, by (1 - cos)^falloff or by Fresnel's law.
  bool variable_reflection = false;
  Vec3 reflection_min{0.0};
  bool fresnel = false;
  double reflection_falloff = 1.0;
  // Filter and transmit light is scaled by 1 - reflection.
  bool conserve_energy = false;
  // `reflection { ... metallic m }`: the reflection tinted by the pigment, less at grazing
  // angles, as metallic highlights are (render/variable_reflection.hpp).
  double reflection_metallic = 0.0;
  double metallic = 0.0; // 0..1: highlights (and reflection) tinted by the pigment
  // POV-Ray 3.7's `emission`: light the surface gives off itself, like ambient but not
  // multiplied by the global ambient_light.
  Vec3 emission{0.0};

  bool operator==(const Finish&) const = default;
};

struct Normal {
  PatternSpace space;      // solid: no perturbation
  double amount = 0.0;     // bump height: `bumps 0.5`
  double accuracy = 0.02;  // patterns without a normal of their own: the sampling distance
};

struct Interior {
  double ior = 1.0;
  // POV-Ray's fade: light crossing d units inside keeps att + (1 - att) fade_color, with
  // att = 1 / (1 + (d / fade_distance)^fade_power), or exp(-d / fade_distance) for
  // fade_power >= 1000 (render/interior_fade.hpp). fade_distance 0: no fade.
  double fade_distance = 0.0;
  double fade_power = 0.0;
  Vec3 fade_color{0.0};

  bool operator==(const Interior&) const = default;
};

struct Texture;
using TexturePtr = std::shared_ptr<const Texture>;

// POV-Ray's texture patterns: at each point a pattern picks whole textures.
//   blocks   `checker texture { A } texture { B }`: the block number picks one texture
//   map      `PATTERN texture_map { [v T] ... }`: as a colour map picks colours; between two
//            entries both textures are shaded and their colours mixed
//   average  `average texture_map { [w T] ... }`: every texture, weighted by w / sum of w
struct TextureMap {
  enum class Kind { blocks, map, average };
  Kind kind = Kind::blocks;
  PatternSpace space;                // blocks and map: the pattern
  std::vector<double> values;        // map: the entries' values, ascending; average: weights
  std::vector<TexturePtr> textures;  // blocks: by block number; map, average: by entry
};

struct Texture {
  Pigment pigment;
  Finish finish;
  Normal normal;
  // Set: the texture is this pattern of textures, and its own pigment, finish and normal
  // are not used.
  std::shared_ptr<const TextureMap> map;
  // Layered textures (`texture { A } texture { B }`: the later one lies on top): the layer
  // under this one, seen where this one's pigment lets light through; null for the last.
  TexturePtr below;
};

// `upper` laid over `lower`: under upper's lowest layer.
inline Texture layered_on(const Texture& lower, Texture upper) {
  upper.below = upper.below ? std::make_shared<const Texture>(layered_on(lower, *upper.below))
                            : std::make_shared<const Texture>(lower);
  return upper;
}

// POV-Ray's default texture: black pigment, the default finish, no normal.
inline Texture default_texture() { return Texture{}; }

}  // namespace convray::scene
