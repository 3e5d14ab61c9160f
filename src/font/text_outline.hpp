#pragma once
// POV-Ray's text objects: the outlines of a string set in a TrueType font (read by FreeType),
// placed as the povray binary places them (measured through its min_extent and pictures):
// one unit per em; the pen starts at the origin, less the first glyph's left side bearing (so
// that the first glyph starts at x = 0); each glyph's advance, the font's kerning of the pair
// ('kern' table) and the text's offset move the pen along.
#include <string>

#include "scene/object.hpp"
#include "util/error.hpp"

namespace convray::font {

// The glyphs of `text` (bytes as character codes) in the font file at `path`, extruded to
// `thickness`; `offset` is added to the pen after every character. Throws InputError at `loc`
// for a file FreeType cannot read as a font or a font whose outlines are not quadratic
// (OpenType CFF).
scene::Text text_outline(const std::string& path, const std::string& text, double thickness,
                         const Vec2& offset, const SourceLoc& loc);

}  // namespace convray::font
