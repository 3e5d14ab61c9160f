#pragma once
#include <iosfwd>
#include <memory>

#include "app/render_options.hpp"
#include "render/render_scene.hpp"
#include "sdl/options.hpp"

namespace convray::app {

// `convray SCENE.pov`: parses the scene, builds its objects, renders and writes the image.
// Returns the exit code: 0; 2 for bad input (scene, mesh, options; the message on `err` as
// file:line:col, no image written); 1 for an internal failure.
int run_render(const RenderOptions& options, std::ostream& out, std::ostream& err);

// What the render hands the parser for one frame (clock, image size, folders, declares) and
// the renderer (size, anti-aliasing): shared with the Python module's render().
sdl::ParseOptions scene_parse_options(const RenderOptions& options, const FrameClock& frame,
                                      std::shared_ptr<sdl::MeshLibrary> meshes);
render::RenderSettings render_settings(const RenderOptions& options);

}  // namespace convray::app
