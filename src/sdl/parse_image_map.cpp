// image_map { [TYPE] "FILE" [gamma G] [map_type N] [once] [interpolate N]
//             [filter all F] [transmit all T] [use_color | use_index] }
// The picture is read through ParseOptions::image_reader; its colours are brought into the
// scene's working space once the scene is read (they depend on its final assumed_gamma).
#include <cmath>

#include "scene/image_map.hpp"
#include "sdl/image_reader.hpp"
#include "sdl/item_parsers.hpp"
#include "sdl/pattern_items.hpp"

namespace convray::sdl::items {

namespace {

constexpr std::string_view kFileTypes[] = {"gif", "tga",  "iff", "ppm", "pgm", "png",
                                           "jpeg", "tiff", "sys", "exr", "hdr"};
constexpr std::string_view kWords[] = {"map_type", "once",     "interpolate", "filter",
                                       "transmit", "use_color", "use_colour", "use_index",
                                       "gamma"};

// The sRGB transfer curve, inverted (IEC 61966-2-1): a display-encoded value to linear light.
double srgb_to_linear(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

struct ImageOptions {
  double file_gamma = 0.0;  // 0: the file's own (sRGB for 8 and 16 bit files, linear for float)
  double filter_all = 0.0, transmit_all = 0.0;
};

// One stored value to the scene's working space: decoded to linear light, then (POV-Ray
// computing in the space of assumed_gamma) encoded with 1 / assumed_gamma. A pre-3.7 scene
// without assumed_gamma renders without gamma correction: the file's values as they are.
double working_value(double stored, bool linear_file, const ImageOptions& options,
                     const scene::GlobalSettings& settings) {
  if (!settings.gamma_correction) return stored;
  double linear = stored;
  if (options.file_gamma > 0.0) {
    linear = std::pow(std::max(stored, 0.0), options.file_gamma);
  } else if (!linear_file) {
    linear = srgb_to_linear(stored);
  }
  return settings.assumed_gamma == 1.0 ? linear
                                       : std::pow(std::max(linear, 0.0), 1.0 / settings.assumed_gamma);
}

void fill_pixels(scene::Image& image, const ImageFile& file, const ImageOptions& options,
                 const scene::GlobalSettings& settings) {
  image.pixels.resize(size_t(file.width) * size_t(file.height));
  for (size_t k = 0; k < image.pixels.size(); ++k) {
    const float* rgba = &file.rgba[k * 4];
    scene::Color& c = image.pixels[k];
    for (int channel = 0; channel < 3; ++channel) {
      c.rgb[channel] = working_value(rgba[channel], file.linear, options, settings);
    }
    // POV-Ray reads an alpha channel as transmit; `transmit all` and `filter all` add theirs.
    c.transmit = std::clamp(1.0 - rgba[3] + options.transmit_all, 0.0, 1.0);
    c.filter = options.filter_all;
  }
}

void parse_image_option(Parser& parser, scene::ImageMap& map, ImageOptions& options) {
  const std::string word = parser.peek().text;
  const SourceLoc loc = take_keyword(parser);
  if (word == "map_type") {
    const int type = int_param(parser, "map_type");
    if (type != 0 && type != 1 && type != 2 && type != 5) {
      parser.fail_unsupported(loc, "image_map's map_type " + std::to_string(type) +
                                       " is not supported yet by convray (0 planar, 1 "
                                       "spherical, 2 cylindrical and 5 torus are)");
    }
    map.projection = scene::ImageProjection(type);
  } else if (word == "once") {
    map.once = true;
  } else if (word == "interpolate") {
    const int kind = int_param(parser, "interpolate");
    if (kind != 0 && kind != 2 && kind != 4) {
      parser.fail(loc, "interpolate must be 2 (bilinear) or 4 (normalized distance), found " +
                           std::to_string(kind));
    }
    map.interpolation = scene::ImageInterpolation(kind);
  } else if (word == "filter" || word == "transmit") {
    if (!accept_word(parser, "all")) {
      parser.fail_unsupported(loc, "'" + word + "' of one palette entry is not supported yet "
                                   "by convray (" + word + " all is)");
    }
    (word == "filter" ? options.filter_all : options.transmit_all) = float_param(parser, word);
  } else if (word == "gamma") {
    options.file_gamma = float_param(parser, "the image's gamma");
    if (!(options.file_gamma > 0.0)) parser.fail(loc, "an image's gamma must be positive");
  }
  // use_color / use_index: how palette images are read; OpenImageIO gives their colours.
}

}  // namespace

std::shared_ptr<const scene::ImageMap> parse_image_map(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "image_map", loc);
  if (at_any_word(parser, kFileTypes)) parser.next();
  const SourceLoc file_at = parser.peek().loc;
  const std::string name = parser.parse_string();
  const std::string path = parser.resolve_file(name, file_at);
  if (!parser.options().image_reader) {
    parser.fail(file_at, "image_map: this command cannot read images");
  }
  auto map = std::make_shared<scene::ImageMap>();
  ImageOptions options;
  while (block.more()) {
    if (!at_any_word(parser, kWords)) block.unexpected(kWords);
    parse_image_option(parser, *map, options);
  }
  ImageFile file;
  try {
    file = parser.options().image_reader->read(path);
  } catch (const InputError& e) {
    parser.fail(file_at, e.what());
  }
  if (file.width < 1 || file.height < 1) parser.fail(file_at, "the image '" + name + "' is empty");
  auto image = std::make_shared<scene::Image>();
  image->width = file.width;
  image->height = file.height;
  parser.at_parse_end([image, file = std::move(file), options](const scene::Scene& scene) {
    fill_pixels(*image, file, options, scene.settings);
  });
  map->image = image;
  return map;
}

}  // namespace convray::sdl::items
