#pragma once
// The parser's three hooks (sdl/options.hpp) answered as the program answers them: trace()
// and the extents by geometry's shapes (geometry_object_queries), image files through the
// image plugin (plugin_image_reader), pigment and pattern functions by the renderer. Every
// command that parses a scene sets all three here, so that a scene reads alike whichever
// command reads it.
#include "sdl/options.hpp"

namespace convray::app {

void use_program_hooks(sdl::ParseOptions& options);

}  // namespace convray::app
