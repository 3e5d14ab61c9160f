#pragma once
#include <iosfwd>

#include "app/render_options.hpp"

namespace convray::app {

// `convray SCENE.pov`: parses the scene, builds its objects, renders and writes the image.
// Returns the exit code: 0; 2 for bad input (scene, mesh, options; the message on `err` as
// file:line:col, no image written); 1 for an internal failure.
int run_render(const RenderOptions& options, std::ostream& out, std::ostream& err);

}  // namespace convray::app
