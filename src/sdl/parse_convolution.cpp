// convray's own object: a convolution surface of skeleton components.
//
//   convolution {
//     radius 1.5      // default support radius R of the components (default 1)
//     strength 1      // default strength s (default 1)
//     offset 0.4      // the surface lies this far from flat parts: T = threshold_for_offset
//     threshold 0.8   // or T itself; neither given: offset = R / 2
//     mesh { "model.ply" [strength s] [radius r] [transforms] [texture] }
//     triangle { <a>, <b>, <c> [strength s] [radius r] ... }
//     segment { <a>, <b> ... }
//     arc { <first>, <through>, <last> ... }
//     point { <c> ... }
//     [object modifiers]
//   }
#include "implicit/threshold.hpp"
#include "sdl/convolution_components.hpp"
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

// The object-level settings, each with where it was given (for messages).
struct ConvolutionSettings {
  ConvolutionDefaults defaults;
  std::optional<SourceLoc> strength_loc;
  std::optional<double> offset, threshold;
  SourceLoc offset_loc, threshold_loc;
};

// Parses `radius`, `strength`, `offset` or `threshold` if the next token is one of them.
bool parse_setting(Parser& parser, ConvolutionSettings& settings) {
  if (at_word(parser, "radius")) {
    const SourceLoc loc = take_keyword(parser);
    settings.defaults.radius = float_param(parser, "radius");
    if (!(settings.defaults.radius > 0.0)) {
      parser.fail(loc, "convolution radius must be positive, found " +
                           number_text(settings.defaults.radius));
    }
  } else if (at_word(parser, "strength")) {
    settings.strength_loc = take_keyword(parser);
    settings.defaults.strength = float_param(parser, "strength");
  } else if (at_word(parser, "offset") || at_word(parser, "threshold")) {
    const bool is_offset = at_word(parser, "offset");
    const SourceLoc loc = take_keyword(parser);
    if (is_offset ? settings.threshold.has_value() : settings.offset.has_value()) {
      parser.fail(loc, "give either offset or threshold, not both");
    }
    (is_offset ? settings.offset_loc : settings.threshold_loc) = loc;
    (is_offset ? settings.offset : settings.threshold) =
        float_param(parser, is_offset ? "offset" : "threshold");
  } else {
    return false;
  }
  return true;
}

double resolve_threshold(Parser& parser, const SourceLoc& loc,
                         const ConvolutionSettings& settings) {
  const ConvolutionDefaults& d = settings.defaults;
  if (settings.threshold) {
    if (!(*settings.threshold > 0.0)) {
      parser.fail(settings.threshold_loc, "convolution threshold must be positive, found " +
                                              number_text(*settings.threshold));
    }
    return *settings.threshold;
  }
  const double offset = settings.offset.value_or(0.5 * d.radius);
  if (!(offset >= 0.0 && offset < d.radius)) {
    parser.fail(settings.offset_loc,
                "convolution offset must satisfy 0 <= offset < radius "
                "(offset " +
                    number_text(offset) + ", radius " + number_text(d.radius) + ")");
  }
  const double threshold = implicit::threshold_for_offset(d.strength, d.radius, offset);
  if (!(threshold > 0.0)) {
    parser.fail(settings.strength_loc.value_or(loc),
                "convolution: a threshold from the offset needs a positive strength (found " +
                    number_text(d.strength) + "); give the threshold itself instead");
  }
  return threshold;
}

}  // namespace

scene::ObjectPtr parse_convolution(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "convolution", loc);
  scene::Object object;
  object.loc = loc;
  object.shape = scene::Implicit{};
  ObjectBuilder builder(parser, std::move(object));

  ConvolutionSettings settings;
  std::vector<PendingComponent> components;
  static constexpr std::string_view kOwn[] = {"radius",   "strength", "offset", "threshold", "mesh",
                                              "triangle", "segment",  "arc",    "point"};
  while (block.more()) {
    if (at_convolution_component(parser)) {
      if (builder.modified()) builder.fail_after_modifiers("the convolution's components");
      components.push_back(parse_convolution_component(parser));
    } else if (!parse_setting(parser, settings) && !builder.parse_modifier()) {
      block.unexpected(kOwn, modifier_words());
    }
  }
  if (components.empty()) {
    parser.fail(loc, "convolution has no components (mesh, triangle, segment, arc, point)");
  }
  auto& implicit = std::get<scene::Implicit>(builder.object().shape);
  implicit.object.threshold = resolve_threshold(parser, loc, settings);
  resolve_components(components, settings.defaults, implicit);
  return builder.build();
}

}  // namespace convray::sdl::items
