// `height_field { [TYPE] "FILE" [smooth] [water_level W] [hierarchy B] [modifiers] }`: the
// heights of an image's pixels (geometry/height_field.hpp). The image is read through
// ParseOptions::image_reader. As the povray binary reads them (trace() on small PNGs):
//   palette images   height = index * 256 / 65535
//   8-bit colour     height = (red * 256 + green) / 65535: red the high byte, green the low
//   16-bit grey      height = value / 65535
//   8-bit grey       height = value / 255 (POV-Ray's heights come out up to 1/255 lower)
// `height_field { function ... }` is not supported yet.
#include <cmath>

#include "sdl/image_reader.hpp"
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

constexpr std::string_view kFileTypes[] = {"gif", "tga",  "iff", "ppm", "pgm", "png",
                                           "jpeg", "tiff", "sys", "exr", "hdr"};

int level(float stored, int max) { return int(std::lround(double(stored) * max)); }

// The heights, row 0 at z = 0 (the image's bottom row), or a reason they cannot be taken.
std::vector<double> heights_of(const ImageFile& file, std::string& problem) {
  const size_t count = size_t(file.width) * size_t(file.height);
  std::vector<double> heights(count);
  for (int row = 0; row < file.height; ++row) {
    for (int column = 0; column < file.width; ++column) {
      const size_t pixel = size_t(row) * size_t(file.width) + size_t(column);
      const float* rgba = &file.rgba[pixel * 4];
      double h = 0.0;
      if (!file.palette_indices.empty()) {
        h = file.palette_indices[pixel] * 256.0 / 65535.0;
      } else if (file.grey) {
        h = std::clamp(double(rgba[0]), 0.0, 1.0);
      } else if (file.bits == 8) {
        h = (level(rgba[0], 255) * 256 + level(rgba[1], 255)) / 65535.0;
      } else {
        problem = "a height_field from a " + std::to_string(file.bits) +
                  "-bit colour image is not supported yet by convray (palette, grey and 8-bit "
                  "colour images are)";
        return {};
      }
      heights[size_t(file.height - 1 - row) * size_t(file.width) + size_t(column)] = h;
    }
  }
  return heights;
}

scene::HeightField read_height_field(Parser& parser, const std::string& name,
                                     const SourceLoc& file_at) {
  const std::string path = parser.resolve_file(name, file_at);
  if (!parser.options().image_reader) {
    parser.fail(file_at, "height_field: this command cannot read images");
  }
  ImageFile file;
  try {
    file = parser.options().image_reader->read(path);
  } catch (const InputError& e) {
    parser.fail(file_at, e.what());
  }
  if (file.width < 2 || file.height < 2) {
    parser.fail(file_at, "a height_field needs an image of at least 2 x 2 pixels");
  }
  std::string problem;
  scene::HeightField field;
  field.columns = file.width;
  field.rows = file.height;
  field.heights = heights_of(file, problem);
  if (!problem.empty()) parser.fail_unsupported(file_at, problem);
  return field;
}

}  // namespace

scene::ObjectPtr parse_height_field(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "height_field", loc);
  if (at_word(parser, "function")) {
    parser.fail_unsupported_here(
        "a height_field made from a function is not supported yet by convray (from an image "
        "file it is)");
  }
  if (at_word(parser, "pot")) {
    // Fractint's 16-bit format: a GIF twice as wide, high bytes left, low bytes right, as
    // palette indices, which OpenImageIO does not give.
    parser.fail_unsupported_here(
        "a height_field from a Fractint 'pot' file is not supported yet by convray");
  }
  if (at_any_word(parser, kFileTypes)) parser.next();
  const SourceLoc file_at = parser.peek().loc;
  const std::string name = parser.parse_string();
  scene::Object object;
  object.shape = read_height_field(parser, name, file_at);
  object.loc = loc;
  // The height field's own keywords may stand among the object's modifiers.
  static constexpr std::string_view kOwn[] = {"smooth", "water_level", "hierarchy"};
  return parse_modifiers(block, std::move(object), kOwn, [&parser](ObjectBuilder& builder) {
    auto& field = std::get<scene::HeightField>(builder.object().shape);
    if (accept_word(parser, "smooth")) {
      field.smooth = true;
    } else if (accept_word(parser, "water_level")) {
      field.water_level = float_param(parser, "water_level");
    } else if (accept_word(parser, "hierarchy")) {
      optional_bool(parser);  // the triangles always go into a BVH
    } else {
      return false;
    }
    return true;
  });
}

}  // namespace convray::sdl::items
