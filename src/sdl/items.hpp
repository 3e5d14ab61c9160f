#pragma once
// Scene items: the parts of the language that describe things (objects, textures, camera,
// lights, atmosphere), parsed from the Parser's plain tokens into scene records. The parser
// core (parser.cpp) calls these; they call back into it only through Parser's public API.
#include "scene/scene.hpp"
#include "sdl/parser.hpp"
#include "sdl/value.hpp"

namespace convray::sdl {

// If the next token starts an item that can be declared (`#declare X = ...`) or used as a
// value — an object, texture, pigment, finish, normal, interior, color_map, transform,
// camera or light_source — parses it into `out` and returns true; otherwise consumes nothing
// and returns false.
bool parse_item(Parser& parser, Value& out);

// One top-level statement of a scene: camera, light_source, an object, background, fog,
// sky_sphere, global_settings. Fails with a clear message on anything else.
void parse_statement(Parser& parser, scene::Scene& scene);

// The first stand-in for an unsupported object in `object`'s tree (CSG children, clipping and
// bounding objects), or null.
const scene::UnsupportedObject* find_unsupported(const scene::Object& object);

}  // namespace convray::sdl
