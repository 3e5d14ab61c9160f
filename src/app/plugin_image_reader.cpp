#include "app/plugin_image_reader.hpp"

#include "core/image_plugin.hpp"
#include "core/png_palette.hpp"

namespace convray::app {

namespace {

class PluginImageReader : public sdl::ImageReader {
 public:
  sdl::ImageFile read(const std::string& path) const override {
    image_plugin::ReadImage image = image_plugin::read(path);
    sdl::ImageFile file;
    file.width = image.width;
    file.height = image.height;
    file.linear = image.linear;
    file.bits = image.bits;
    file.grey = image.grey;
    file.rgba = std::move(image.rgba);
    file.palette_indices = png_palette_indices(path, image.width, image.height);
    return file;
  }
};

}  // namespace

std::shared_ptr<const sdl::ImageReader> plugin_image_reader() {
  return std::make_shared<PluginImageReader>();
}

}  // namespace convray::app
