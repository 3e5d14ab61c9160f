// What surrounds the objects: background { color }, fog { ... }, sky_sphere { pigments },
// and global_settings { ... }.
#include "sdl/item_parsers.hpp"
#include "sdl/pattern_items.hpp"

namespace convray::sdl::items {

scene::Color parse_background(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "background", loc);
  const scene::Color color = color_param(parser);
  if (block.more()) block.unexpected({});
  return color;
}

namespace {

constexpr std::string_view kFogWords[] = {
    "fog_type",   "distance",   "color",   "colour", "fog_offset", "fog_alt",
    "turbulence", "turb_depth", "octaves", "omega",  "lambda",     "up",
    "translate",  "rotate",     "scale",   "matrix", "transform"};

void parse_fog_item(Parser& parser, Block& block, scene::Fog& fog) {
  if (auto transform = parse_transform_modifier(parser)) {
    fog.up = transform->vector(fog.up);
    return;
  }
  if (at_color_start(parser)) {
    fog.color = color_param(parser);
    return;
  }
  if (!at_any_word(parser, kFogWords)) block.unexpected(kFogWords);
  const std::string word = parser.peek().text;
  const SourceLoc loc = take_keyword(parser);
  if (word == "fog_type") {
    const int type = int_param(parser, "fog_type");
    if (type != 1 && type != 2) {
      parser.fail(loc,
                  "fog_type must be 1 (constant) or 2 (ground), found " + std::to_string(type));
    }
    fog.kind = scene::Fog::Kind(type);
  } else if (word == "distance") {
    fog.distance = float_param(parser, "distance");
    if (!(fog.distance > 0.0)) {
      parser.fail(loc, "fog distance must be positive, found " + number_text(fog.distance));
    }
  } else if (word == "fog_offset") {
    fog.offset = float_param(parser, word);
  } else if (word == "fog_alt") {
    fog.altitude = float_param(parser, word);
  } else if (word == "turbulence") {
    fog.turbulence.amount = vector_param(parser, word);
    warn_once(parser, loc, "fog turbulence is not rendered by convray: the fog's density is even");
  } else if (word == "octaves") {
    fog.turbulence.octaves = int_param(parser, word);
  } else if (word == "omega") {
    fog.turbulence.omega = float_param(parser, word);
  } else if (word == "lambda") {
    fog.turbulence.lambda = float_param(parser, word);
  } else if (word == "up") {
    fog.up = vector_param(parser, word);
    if (fog.up == Vec3(0.0)) parser.fail(loc, "fog up vector must not be 0");
  } else {  // turb_depth
    float_param(parser, word);
    warn_once(parser, loc, "'turb_depth' is ignored by convray");
  }
}

}  // namespace

scene::Fog parse_fog(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "fog", loc);
  scene::Fog fog;
  while (block.more()) parse_fog_item(parser, block, fog);
  if (!(fog.distance > 0.0)) parser.fail(loc, "fog needs a distance");
  return fog;
}

scene::SkySphere parse_sky_sphere(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "sky_sphere", loc);
  scene::SkySphere sky;
  // A declared sky_sphere to start from: `sky_sphere { S_Cloud1 }` (skies.inc), whose
  // pigments further ones are layered on and whose placement further transforms move.
  if (const Value* declared = parser.peek_declared()) {
    const auto* base = declared->get<std::shared_ptr<const scene::SkySphere>>();
    if (base == nullptr) {
      parser.fail_here("expected a sky_sphere, found '" + parser.peek().text + "' (" +
                       type_name(*declared) + ")");
    }
    sky = **base;
    parser.next();
  }
  static constexpr std::string_view kWords[] = {"pigment", "emission", "translate", "rotate",
                                                "scale",   "matrix",   "transform"};
  while (block.more()) {
    if (at_word(parser, "pigment")) {
      sky.pigments.push_back(parse_pigment(parser, scene::Pigment{}));
    } else if (auto transform = parse_transform_modifier(parser)) {
      sky.transform = sky.transform.then(*transform);
    } else if (at_word(parser, "emission")) {
      const SourceLoc item_loc = take_keyword(parser);
      color_param(parser);
      warn_once(parser, item_loc, "sky_sphere emission is ignored by convray");
    } else {
      block.unexpected(kWords);
    }
  }
  if (sky.pigments.empty()) parser.fail(loc, "sky_sphere needs at least one pigment");
  return sky;
}

namespace {

constexpr std::string_view kSettingWords[] = {
    "assumed_gamma",   "max_trace_level",   "ambient_light",   "adc_bailout", "radiosity",
    "photons",         "number_of_waves",   "noise_generator", "charset",     "hf_gray_16",
    "irid_wavelength", "max_intersections", "mm_per_unit",     "subsurface"};

void parse_ignored_setting(Parser& parser, const std::string& word, const SourceLoc& loc) {
  if (word == "radiosity" || word == "photons" || word == "subsurface") {
    skip_braced(parser, word, loc);
  } else if (word == "charset") {
    parser.next();  // ascii, utf8, sys
  } else if (word == "hf_gray_16") {
    optional_bool(parser);
  } else if (word == "irid_wavelength") {
    color_param(parser);
  } else {
    float_param(parser, word);
  }
  warn_once(parser, loc, "global setting '" + word + "' is ignored by convray");
}

}  // namespace

void parse_global_settings(Parser& parser, scene::GlobalSettings& settings) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "global_settings", loc);
  while (block.more()) {
    if (!at_any_word(parser, kSettingWords)) block.unexpected(kSettingWords);
    const std::string word = parser.peek().text;
    const SourceLoc item_loc = take_keyword(parser);
    if (word == "assumed_gamma") {
      settings.assumed_gamma = float_param(parser, word);
      // Rendered as POV-Ray 3.7 does (render_scene.cpp decodes the working space at the
      // end; image maps are read into it): no warning.
      parser.note_assumed_gamma();
    } else if (word == "max_trace_level") {
      settings.max_trace_level = int_param(parser, word);
      if (settings.max_trace_level < 1) {
        parser.fail(item_loc, "max_trace_level must be at least 1");
      }
    } else if (word == "ambient_light") {
      settings.ambient_light = rgb_param(parser, "ambient_light");
    } else if (word == "adc_bailout") {
      settings.adc_bailout = float_param(parser, word);
    } else {
      parse_ignored_setting(parser, word, item_loc);
    }
  }
}

}  // namespace convray::sdl::items
