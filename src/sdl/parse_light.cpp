// light_source { [LIGHT_ID] | <location>, color  [spotlight | parallel | shadowless]
//                [point_at v] [radius f] [falloff f] [tightness f] [fade_distance f]
//                [fade_power f] [area_light axis1, axis2, n1, n2 [adaptive n] [jitter]
//                [circular] [orient]] [transforms] }
// Transforms move the position and point_at (points) and the area light's axes (vectors).
#include "sdl/item_parsers.hpp"

namespace convray::sdl::items {

namespace {

// clang-format off
constexpr std::string_view kLightWords[] = {
    "spotlight", "parallel", "shadowless", "point_at", "radius", "falloff", "tightness",
    "fade_distance", "fade_power", "area_light", "adaptive", "jitter", "circular", "orient",
    "looks_like", "projected_through", "media_interaction", "media_attenuation", "photons",
    "area_illumination", "translate", "rotate", "scale", "matrix", "transform"};
// clang-format on

// A light while its items are read: area_light settings may come before `area_light`
// itself (POV-Ray takes them in any order), and the transforms apply at the end.
struct LightItems {
  scene::Light light;
  scene::AreaLight area;
  bool has_area = false;
  std::optional<SourceLoc> area_setting_loc;  // adaptive, jitter, circular, orient
  scene::Transform transform;
};

LightItems items_of(const scene::Light& light) {
  LightItems items;
  items.light = light;
  if (light.area) {
    items.area = *light.area;
    items.has_area = true;
  }
  return items;
}

void parse_area_light(Parser& parser, const SourceLoc& loc, LightItems& items) {
  scene::AreaLight& area = items.area;
  area.axis1 = vector_param(parser, "the area light's first axis");
  parser.accept_comma();
  area.axis2 = vector_param(parser, "the area light's second axis");
  parser.accept_comma();
  area.size1 = int_param(parser, "the number of lights along axis 1");
  parser.accept_comma();
  area.size2 = int_param(parser, "the number of lights along axis 2");
  if (area.size1 < 1 || area.size2 < 1) {
    parser.fail(loc, "area_light needs at least 1 light along each axis");
  }
  items.has_area = true;
}

void parse_area_setting(Parser& parser, const std::string& word, const SourceLoc& loc,
                        LightItems& items) {
  if (!items.area_setting_loc) items.area_setting_loc = loc;
  scene::AreaLight& area = items.area;
  if (word == "adaptive") area.adaptive = int_param(parser, word);
  if (word == "jitter") area.jitter = optional_bool(parser);
  if (word == "circular") area.circular = optional_bool(parser);
  if (word == "orient") area.orient = optional_bool(parser);
}

// Modifiers that are parsed and not rendered.
void parse_ignored_light_item(Parser& parser, const std::string& word, const SourceLoc& loc) {
  if (word == "looks_like" || word == "projected_through") {
    Block block(parser, word, loc);
    while (block.more()) {
      if (!at_object(parser)) block.unexpected({});
      parse_object(parser);
    }
  } else if (word == "photons") {
    skip_braced(parser, word, loc);
  } else {
    const bool on = optional_bool(parser);  // media_interaction, media_attenuation, area_...
    if (word == "media_attenuation" && on) {
      // What it asks for (shadows dimmed by the media they cross) needs media, which convray
      // leaves out (each medium with its own warning).
      warn_once(parser, loc,
                "'media_attenuation' is ignored by convray: it renders no media, so this "
                "light's shadow rays are not dimmed by media");
      return;
    }
    if (word != "area_illumination") return;  // media_interaction: no media, nothing to do
  }
  warn_once(parser, loc, "'" + word + "' is ignored by convray");
}

void parse_light_float(Parser& parser, const std::string& word, scene::Light& light) {
  const double value = float_param(parser, word);
  if (word == "radius") light.radius = value;
  if (word == "falloff") light.falloff = value;
  if (word == "tightness") light.tightness = value;
  if (word == "fade_distance") light.fade_distance = value;
  if (word == "fade_power") light.fade_power = value;
}

void parse_light_item(Parser& parser, Block& block, LightItems& items) {
  if (auto step = parse_transform_modifier(parser)) {
    items.transform = items.transform.then(*step);
    return;
  }
  if (at_word(parser, "cylinder")) {
    parser.fail_unsupported_here("cylindrical light sources are not supported yet");
  }
  if (!at_any_word(parser, kLightWords)) block.unexpected(kLightWords);
  const std::string word = parser.peek().text;
  const SourceLoc loc = take_keyword(parser);
  scene::Light& light = items.light;
  if (word == "spotlight") {
    light.kind = scene::Light::Kind::spotlight;
  } else if (word == "parallel") {
    light.kind = scene::Light::Kind::parallel;
  } else if (word == "shadowless") {
    light.shadowless = true;
  } else if (word == "point_at") {
    light.point_at = vector_param(parser, word);
  } else if (word == "radius" || word == "falloff" || word == "tightness" ||
             word == "fade_distance" || word == "fade_power") {
    parse_light_float(parser, word, light);
  } else if (word == "area_light") {
    parse_area_light(parser, loc, items);
  } else if (word == "adaptive" || word == "jitter" || word == "circular" || word == "orient") {
    parse_area_setting(parser, word, loc, items);
  } else {
    parse_ignored_light_item(parser, word, loc);
  }
}

}  // namespace

scene::Light placed_light(scene::Light light, const scene::Transform& transform) {
  light.position = transform.point(light.position);
  light.point_at = transform.point(light.point_at);
  if (light.area) {
    light.area->axis1 = transform.vector(light.area->axis1);
    light.area->axis2 = transform.vector(light.area->axis2);
  }
  return light;
}

scene::Light parse_light_modifiers(Parser& parser, Block& block, const scene::Light& start) {
  LightItems items = items_of(start);
  while (block.more()) parse_light_item(parser, block, items);
  scene::Light& light = items.light;
  const scene::Transform& transform = items.transform;
  light.position = transform.point(light.position);
  light.point_at = transform.point(light.point_at);
  if (light.kind != scene::Light::Kind::point && light.point_at == light.position) {
    parser.fail(block.loc(),
                "a spotlight or parallel light must point_at a point other than "
                "its location");
  }
  if (items.has_area) {
    items.area.axis1 = transform.vector(items.area.axis1);
    items.area.axis2 = transform.vector(items.area.axis2);
    light.area = items.area;
  } else if (items.area_setting_loc) {
    warn_once(parser, *items.area_setting_loc,
              "area light settings without area_light are ignored (as POV-Ray does)");
  }
  return light;
}

scene::Light parse_light(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "light_source", loc);
  scene::Light light;
  if (auto declared = accept_declared<scene::Light>(parser, "a light_source")) {
    light = *declared;
  } else {
    light.position = vector_param(parser, "the light's location");
    parser.accept_comma();
    light.color = color_param(parser);
  }
  return parse_light_modifiers(parser, block, light);
}

}  // namespace convray::sdl::items
