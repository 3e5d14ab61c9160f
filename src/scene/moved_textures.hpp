#pragma once
// Textures are evaluated in the space their object is placed in (scene/texture.hpp), so every
// transform applied to an object after a texture was given is appended to that texture's
// pattern transforms, including the textures of everything inside the object. The parser
// moves textures as it reads transforms; geometry/ moves them where it flattens a shared
// placement (an instance, scene/instance.hpp) that it cannot trace as one.
//
// A texture that looks the same everywhere (solid pigments, no normal perturbation, no
// texture pattern) is not moved at all: it is shared as it is, so that a union of 10^6
// plain-coloured members moved by its transform costs no copies.
#include "scene/object.hpp"

namespace convray::scene {

// Whether the texture's look depends on where it is evaluated (a pattern somewhere in it).
bool depends_on_position(const Texture& texture);

// Whether two textures that depend on no position look the same (colour, finish, layers):
// the default texture a scene gives every top-level object is a record of its own each time.
bool same_everywhere(const Texture& a, const Texture& b);

// Where a texture is evaluated moves with `transform`: appended to the pattern transforms of
// its pigment, normal and texture pattern, and of the textures below it or picked by it.
void move_texture(Texture& texture, const Transform& transform);
// A pigment moved by `transform`, with the pigments of its pigment_map.
void move_pigment(Pigment& pigment, const Transform& transform);
// A moved copy of `texture`, or `texture` itself when nothing in it depends on position.
TexturePtr moved_texture(const TexturePtr& texture, const Transform& transform);

// Moves every texture inside `object` (CSG children, mesh faces, blob and convolution
// components; not the object's own texture), copying only the shared records it changes: a
// child whose textures depend on no position is shared as it is, and a texture shared by
// several children is moved once. An instance's inner textures are in its own space and move
// with its transform: nothing inside one is touched.
void move_inner_textures(Object& object, const Transform& transform);

}  // namespace convray::scene
