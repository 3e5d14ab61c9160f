#pragma once
// The item parsers behind parse_item and parse_statement (items.hpp), one file per concept.
// Each `parse_X` is called with its keyword at peek() and consumes the whole item.
#include <optional>
#include <string_view>

#include "scene/moved_textures.hpp"
#include "scene/object.hpp"
#include "scene/scene.hpp"
#include "scene/texture.hpp"
#include "sdl/item_helpers.hpp"
#include "sdl/parser.hpp"
#include "sdl/value.hpp"

namespace convray::sdl::items {

// --- Objects (parse_object.cpp, parse_shapes.cpp, parse_mesh.cpp, parse_csg.cpp,
// parse_blob.cpp, parse_convolution.cpp).

// Whether the next token starts an object: a shape keyword, a CSG keyword or `object`.
bool at_object(Parser& parser);
Keywords object_words();  // for "did you mean"
scene::ObjectPtr parse_object(Parser& parser);
// POV-Ray objects convray does not have yet (text, lathe, isosurface, ...): parse_object
// fails on them; a declaration gets an empty object and a warning instead, so that include
// files that declare them (shapes.inc) can still be used.
bool at_unsupported_object(Parser& parser);
scene::ObjectPtr parse_unsupported_object_as_empty(Parser& parser);
// `object { ... }` at the top level of a scene, where POV-Ray also lets it name a declared
// light_source: adds the object or the light to `scene`.
void parse_top_level_object(Parser& parser, scene::Scene& scene);
// A top-level object without a texture gets the #default texture in force where it ends, as
// in POV-Ray (CSG children without one inherit their parent's instead, in geometry/).
scene::ObjectPtr with_default_texture(Parser& parser, scene::ObjectPtr object);
// An object placed in the scene at `at`: with the default texture if it has none; an error if
// it is, or contains, a declared stand-in for an unsupported object (`sor`, `text`, ...).
scene::ObjectPtr placed_object(Parser& parser, scene::ObjectPtr object, const SourceLoc& at);
// The light_sources inside a placed object's CSGs (at any depth), placed as the CSGs are,
// appended to the scene's lights.
void add_csg_lights(const scene::Object& object, scene::Scene& scene);
// A light moved by `transform`: its location, point_at and area axes.
scene::Light placed_light(scene::Light light, const scene::Transform& transform);

scene::ObjectPtr parse_sphere(Parser& parser);
scene::ObjectPtr parse_box(Parser& parser);
scene::ObjectPtr parse_plane(Parser& parser);
scene::ObjectPtr parse_cylinder(Parser& parser);
scene::ObjectPtr parse_cone(Parser& parser);
scene::ObjectPtr parse_torus(Parser& parser);
scene::ObjectPtr parse_text(Parser& parser);
scene::ObjectPtr parse_prism(Parser& parser);
scene::ObjectPtr parse_superellipsoid(Parser& parser);
scene::ObjectPtr parse_isosurface(Parser& parser);
scene::ObjectPtr parse_lathe(Parser& parser);
scene::ObjectPtr parse_polygon(Parser& parser);
scene::ObjectPtr parse_sor(Parser& parser);
scene::ObjectPtr parse_bicubic_patch(Parser& parser);  // as a mesh of smooth triangles
scene::ObjectPtr parse_height_field(Parser& parser);
scene::ObjectPtr parse_polynomial(Parser& parser);  // poly, cubic, quartic, quadric
scene::ObjectPtr parse_disc(Parser& parser);
scene::ObjectPtr parse_triangle(Parser& parser);  // triangle and smooth_triangle
scene::ObjectPtr parse_mesh(Parser& parser);
scene::ObjectPtr parse_mesh2(Parser& parser);
scene::ObjectPtr parse_csg(Parser& parser);  // union, intersection, difference, merge
scene::ObjectPtr parse_blob(Parser& parser);
scene::ObjectPtr parse_convolution(Parser& parser);

// --- Textures (parse_texture.cpp, parse_pigment.cpp, parse_normal.cpp). Each starts from
// `start` (a copy of what the item modifies: the object's current pigment, the defaults, ...);
// a declared identifier first in the block replaces it.
scene::Texture parse_texture(Parser& parser, const scene::Texture& start);
// What a texture { } holds, from the scene's default texture up to the `closing` token (not
// taken): a texture_map entry or a tiles { } block.
scene::Texture parse_texture_body(Parser& parser, const std::string& closing);
// A texture pattern (parse_texture_map.cpp): `checker texture {A} texture {B}`, `tiles { A }
// tile2 { B }`, `PATTERN [modifiers] texture_map { [v T] ... }`, `average texture_map
// { [w T] ... }`, into `texture`; false when the next token starts none.
bool parse_texture_pattern(Parser& parser, scene::Texture& texture);
// At the end of a texture: a pattern that still lacks its textures is an error at `loc`.
void check_texture_pattern(Parser& parser, const scene::Texture& texture, const SourceLoc& loc);
scene::Pigment parse_pigment(Parser& parser, const scene::Pigment& start);
scene::Finish parse_finish(Parser& parser, const scene::Finish& start);
scene::Normal parse_normal(Parser& parser, const scene::Normal& start);
scene::Interior parse_interior(Parser& parser, const scene::Interior& start);
ColorMap parse_color_map(Parser& parser);  // color_map or colour_map
// image_map { ... } (parse_image_map.cpp), the pattern of a pigment.
std::shared_ptr<const scene::ImageMap> parse_image_map(Parser& parser);

// POV-Ray looks a value v up in a colour map by scanning for the first entry at or above v
// and blending it with the entry before (below the first entry: its colour; at or above the
// last: the last's colour), whatever order the values were written in (woods.inc has maps
// that step back). Returns the map with ascending values that gives the same colour for
// every v: entries the scan never stops at are dropped, the blends they start are kept.
// Equal values in a row make a step.
ColorMap ascending_equivalent(const ColorMap& map);


// material { [M_ID] texture {...} interior {...} [transforms] }: the transforms move the
// texture. A declared material is held as its texture (Value has no material yet), so
// M_ID may also name a texture.
struct ParsedMaterial {
  std::optional<scene::Texture> texture;
  std::optional<scene::Interior> interior;
};
ParsedMaterial parse_material(Parser& parser);

// Where a texture is evaluated moves with the transforms applied after it
// (scene/moved_textures.hpp).
using scene::move_pigment;
using scene::move_texture;
using scene::moved_texture;
// A warp listed in a pigment (or a texture's pattern) acts on the pigments (textures) its map
// picks too, as the povray binary draws them (textures/pigments/warp2.pov): appended to their
// spaces as to the pattern's own. `warp.inner` is ignored: what was listed before the warp
// is already in each space's transform.
void warp_pigment(scene::Pigment& pigment, const scene::Warp& warp);
void warp_texture(scene::Texture& texture, const scene::Warp& warp);
// The transforms and warps of `space` (a pattern whose map entries are being read) applied to
// an entry's pigment or texture.
void place_in_space(scene::Pigment& pigment, const scene::PatternSpace& space);
void place_in_space(scene::Texture& texture, const scene::PatternSpace& space);
// `warp` appended to `space`: what was listed before it becomes its inner transform.
void append_warp(scene::PatternSpace& space, scene::Warp warp);
using scene::move_inner_textures;

// --- Scene settings (parse_camera.cpp, parse_light.cpp, parse_atmosphere.cpp).
scene::Camera parse_camera(Parser& parser);
scene::Light parse_light(Parser& parser);
// The light's modifiers up to the `}` of `block`, applied to `start`.
scene::Light parse_light_modifiers(Parser& parser, Block& block, const scene::Light& start);
scene::Color parse_background(Parser& parser);
scene::Fog parse_fog(Parser& parser);
scene::SkySphere parse_sky_sphere(Parser& parser);
void parse_global_settings(Parser& parser, scene::GlobalSettings& settings);

}  // namespace convray::sdl::items
