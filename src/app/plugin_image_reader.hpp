#pragma once
// The pictures of image_maps (sdl/image_reader.hpp), read through the image plugin
// (core/image_plugin.hpp): convray itself does not link OpenImageIO.
#include <memory>

#include "sdl/image_reader.hpp"

namespace convray::app {

std::shared_ptr<const sdl::ImageReader> plugin_image_reader();

}  // namespace convray::app
