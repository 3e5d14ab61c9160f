// `text { ttf "FONT.ttf" "STRING" THICKNESS, OFFSET [modifiers] }`: the font is found as
// POV-Ray finds it (the scene's folder, the +L folders, POV-Ray's include folder, where
// its fonts are) and its glyph outlines are read by font/ (FreeType).
#include <string>

#include "font/text_outline.hpp"
#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

scene::ObjectPtr parse_text(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "text", loc);
  if (at_word(parser, "internal")) {
    parser.fail_unsupported_here(
        "POV-Ray's internal fonts (text { internal N ... }) are not supported yet by convray: "
        "name a TrueType font with ttf \"FILE.ttf\"");
  }
  parser.expect("ttf", "text (only TrueType fonts: text { ttf \"FILE.ttf\" \"STRING\" ... })");
  const SourceLoc font_at = parser.peek().loc;
  const std::string font = parser.parse_string();
  parser.accept_comma();
  const std::string string = parser.parse_string();
  parser.accept_comma();
  const double thickness = float_param(parser, "the text's thickness");
  parser.accept_comma();
  const Vec3 offset = vector_param(parser, "the text's offset");
  const std::string path = parser.resolve_file(font, font_at, ".ttf");
  scene::Object object;
  // The offset's z is not used: POV-Ray's letters all start in the plane z = 0.
  object.shape = font::text_outline(path, string, thickness, Vec2(offset), font_at);
  object.loc = loc;
  return parse_modifiers(block, std::move(object));
}

}  // namespace convray::sdl::items
