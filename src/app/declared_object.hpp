#pragma once
// `--object NAME`: a convolution object or blob declared in a scene file
// (`#declare NAME = convolution { ... }`), as `convray field` and `convray polygonize` use it.
#include <string>

#include "scene/object.hpp"
#include "sdl/parser.hpp"

namespace convray::app {

// The declared object `name` of a parsed scene, which must be a convolution object or a blob.
// Throws InputError (at the scene, or at the declaration) otherwise.
const scene::Object& declared_implicit(const sdl::ParseResult& parsed,
                                       const std::string& scene_path, const std::string& name);

}  // namespace convray::app
