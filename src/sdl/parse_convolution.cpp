// convray's own object: a convolution surface of skeleton components.
//
//   convolution {
//     radius 1.5      // default support radius R of the components (default 1)
//     strength 1      // default strength s (default 1)
//     offset 0.4      // the surface lies this far from flat parts: T = threshold_for_offset
//     threshold 0.8   // or T itself; neither given: offset = R / 2
//     kernel quartic  // the default; or `kernel cauchy [s]` (McCormack and Sherstyuk's
//                     // 1/(1 + s^2 r^2)^2, s > 0, default 1; radius is then the margin of
//                     // each primitive's truncation box)
//     mesh { "model.ply" [strength s] [radius r] [transforms] [texture] }
//     triangle { <a>, <b>, <c> [strength s] [radius r] ... }
//     segment { <a>, <b> ... }
//     arc { <first>, <through>, <last> ... }
//     point { <c> ... }
//     [object modifiers]
//   }
#include <cmath>

#include "field/threshold.hpp"
#include "sdl/convolution_components.hpp"
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"
#include "sdl/parse_log.hpp"

namespace convray::sdl::items {

namespace {

// The object-level settings, each with where it was given (for messages).
struct ConvolutionSettings {
  ConvolutionDefaults defaults;
  std::optional<SourceLoc> strength_loc;
  std::optional<double> offset, threshold;
  SourceLoc offset_loc, threshold_loc;
  field::Kernel kernel;
};

// After `kernel`: `quartic`, or `cauchy` with an optional sharpness s > 0.
void parse_kernel(Parser& parser, field::Kernel& kernel) {
  if (accept_word(parser, "quartic")) {
    kernel = {};
  } else if (accept_word(parser, "cauchy")) {
    kernel.type = field::KernelType::cauchy;
    kernel.sharpness = 1.0;
    if (at_float_start(parser)) {
      const SourceLoc loc = parser.peek().loc;
      kernel.sharpness = float_param(parser, "the cauchy kernel's sharpness s");
      if (!(kernel.sharpness > 0.0 && std::isfinite(kernel.sharpness))) {
        parser.fail(loc, "kernel cauchy: the sharpness s must be positive, found " +
                             number_text(kernel.sharpness));
      }
    }
  } else {
    parser.fail_here("kernel must be quartic or cauchy, found '" + parser.peek().text + "'");
  }
}

// Parses `radius`, `strength`, `offset` or `threshold` if the next token is one of them.
bool parse_setting(Parser& parser, ConvolutionSettings& settings) {
  if (at_word(parser, "radius")) {
    const SourceLoc loc = take_keyword(parser);
    settings.defaults.radius = float_param(parser, "radius");
    if (!(settings.defaults.radius > 0.0)) {
      parser.fail(loc, "convolution radius must be positive, found " +
                           number_text(settings.defaults.radius));
    }
  } else if (at_word(parser, "kernel")) {
    take_keyword(parser);
    parse_kernel(parser, settings.kernel);
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

// Fields are sums of strength-weighted closed forms, their gradients products of them: a
// threshold within 1e+-290 leaves them room to neither overflow nor lose precision in
// subnormals (strengths of 1e308 or 1e-320 otherwise shade as flat silhouettes).
void check_threshold_in_range(Parser& parser, const SourceLoc& loc, double threshold) {
  if (threshold >= 1e-290 && threshold <= 1e290) return;
  parser.fail(loc, "convolution: the threshold " + number_text(threshold) +
                       " is outside what double precision evaluates safely (1e-290 to 1e290); "
                       "scale the strengths (the surface depends only on strength / threshold)");
}

double resolve_threshold(Parser& parser, const SourceLoc& loc,
                         const ConvolutionSettings& settings) {
  const ConvolutionDefaults& d = settings.defaults;
  if (settings.threshold) {
    if (!(*settings.threshold > 0.0)) {
      parser.fail(settings.threshold_loc, "convolution threshold must be positive, found " +
                                              number_text(*settings.threshold));
    }
    check_threshold_in_range(parser, settings.threshold_loc, *settings.threshold);
    return *settings.threshold;
  }
  try {
    field::check_radius_in_range(d.radius);
  } catch (const std::invalid_argument& e) {
    parser.fail(loc, std::string("convolution: ") + e.what());
  }
  const double offset = settings.offset.value_or(0.5 * d.radius);
  if (!(offset >= 0.0 && offset < d.radius)) {
    parser.fail(settings.offset_loc,
                "convolution offset must satisfy 0 <= offset < radius "
                "(offset " +
                    number_text(offset) + ", radius " + number_text(d.radius) + ")");
  }
  // The plane's field at distance `offset`, under the object's kernel.
  const double threshold = field::plane_threshold(settings.kernel, d.strength, d.radius, offset);
  if (!(threshold > 0.0)) {
    parser.fail(settings.strength_loc.value_or(loc),
                "convolution: a threshold from the offset needs a positive strength (found " +
                    number_text(d.strength) + "); give the threshold itself instead");
  }
  check_threshold_in_range(parser, settings.strength_loc.value_or(loc), threshold);
  return threshold;
}

// `convray view`'s live edit of this header, if any: its radius and offset replace what the
// scene wrote (a threshold written gives way to the offset), as an edit of the text would.
void apply_edit(Parser& parser, const SourceLoc& loc, ConvolutionSettings& settings) {
  const auto& edits = parser.options().convolution_edits;
  if (!edits) return;
  for (const ConvolutionEdit& edit : *edits) {
    if (!same_place(edit.loc, loc)) continue;
    settings.defaults.radius = edit.radius;
    settings.offset = edit.offset;
    settings.threshold.reset();
    settings.offset_loc = loc;
  }
}

void note_header(Parser& parser, const SourceLoc& loc, const ConvolutionSettings& settings) {
  if (!parser.options().log) return;
  parser.options().log->note_convolution({loc, settings.defaults.radius,
                                          settings.defaults.strength, settings.offset,
                                          settings.threshold, settings.kernel});
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
  static constexpr std::string_view kOwn[] = {"radius",  "strength", "offset",
                                              "threshold", "kernel", "mesh",
                                              "triangle", "segment", "arc", "point"};
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
  if (settings.kernel.type == field::KernelType::cauchy) {
    for (const PendingComponent& component : components) {
      if (component.kind == scene::Implicit::Kind::arc) {
        parser.fail(component.loc,
                    "kernel cauchy supports points, segments and triangles (meshes), not arcs");
      }
    }
  }
  apply_edit(parser, loc, settings);
  note_header(parser, loc, settings);
  auto& implicit = std::get<scene::Implicit>(builder.object().shape);
  implicit.header_loc = loc;
  implicit.object.kernel = settings.kernel;
  implicit.object.threshold = resolve_threshold(parser, loc, settings);
  resolve_components(components, settings.defaults, implicit);
  return builder.build();
}

}  // namespace convray::sdl::items
