#include "app/parse_hooks.hpp"

#include "app/geometry_object_queries.hpp"
#include "app/plugin_image_reader.hpp"
#include "render/function_sources.hpp"

namespace convray::app {

void use_program_hooks(sdl::ParseOptions& options) {
  options.object_queries = geometry_object_queries();
  options.image_reader = plugin_image_reader();
  options.color_sources = render::renderer_color_sources();
}

}  // namespace convray::app
