#include "font/text_outline.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <memory>
#include <utility>

namespace convray::font {

namespace {

struct LibraryCloser {
  void operator()(FT_Library library) const { FT_Done_FreeType(library); }
};
struct FaceCloser {
  void operator()(FT_Face face) const { FT_Done_Face(face); }
};
using Library = std::unique_ptr<std::remove_pointer_t<FT_Library>, LibraryCloser>;
using Face = std::unique_ptr<std::remove_pointer_t<FT_Face>, FaceCloser>;

// One glyph's contours as pieces, in font units, as FT_Outline_Decompose walks them (it
// closes every contour).
struct GlyphWalk {
  std::vector<scene::OutlinePiece> pieces;
  Vec2 at{0.0};
  bool cubic = false;

  static Vec2 point(const FT_Vector* v) { return Vec2(double(v->x), double(v->y)); }
  static GlyphWalk& of(void* user) { return *static_cast<GlyphWalk*>(user); }

  static int move_to(const FT_Vector* to, void* user) {
    of(user).at = point(to);
    return 0;
  }
  static int line_to(const FT_Vector* to, void* user) {
    GlyphWalk& walk = of(user);
    const Vec2 end = point(to);
    walk.pieces.push_back({walk.at, 0.5 * (walk.at + end), end});
    walk.at = end;
    return 0;
  }
  static int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    GlyphWalk& walk = of(user);
    const Vec2 end = point(to);
    walk.pieces.push_back({walk.at, point(control), end});
    walk.at = end;
    return 0;
  }
  static int cubic_to(const FT_Vector*, const FT_Vector*, const FT_Vector* to, void* user) {
    of(user).cubic = true;
    of(user).at = point(to);
    return 0;
  }
};

// The pieces of the loaded glyph, clockwise around what they enclose.
GlyphWalk walk_outline(FT_Outline& outline) {
  FT_Outline_Funcs funcs{};
  funcs.move_to = GlyphWalk::move_to;
  funcs.line_to = GlyphWalk::line_to;
  funcs.conic_to = GlyphWalk::conic_to;
  funcs.cubic_to = GlyphWalk::cubic_to;
  GlyphWalk walk;
  FT_Outline_Decompose(&outline, &funcs, &walk);
  // Fonts drawn the PostScript way (counter-clockwise outer contours) are turned around.
  if (FT_Outline_Get_Orientation(&outline) == FT_ORIENTATION_POSTSCRIPT) {
    for (scene::OutlinePiece& piece : walk.pieces) std::swap(piece.a, piece.c);
  }
  return walk;
}

Face open_face(FT_Library library, const std::string& path, const SourceLoc& loc) {
  FT_Face face = nullptr;
  const FT_Error error = FT_New_Face(library, path.c_str(), 0, &face);
  if (error != 0 || face == nullptr) {
    throw InputError(loc, "cannot read the font '" + path + "' (FreeType error " +
                              std::to_string(error) + ")");
  }
  Face owned(face);
  if (!FT_IS_SCALABLE(face) || face->units_per_EM == 0) {
    throw InputError(loc, "'" + path + "' has no outlines (a bitmap font)");
  }
  return owned;
}

}  // namespace

scene::Text text_outline(const std::string& path, const std::string& text, double thickness,
                         const Vec2& offset, const SourceLoc& loc) {
  FT_Library raw_library = nullptr;
  if (FT_Init_FreeType(&raw_library) != 0) throw InputError(loc, "FreeType cannot start");
  const Library library(raw_library);
  const Face face = open_face(raw_library, path, loc);
  const double em = 1.0 / double(face->units_per_EM);

  scene::Text result;
  result.thickness = thickness;
  Vec2 pen(0.0);
  double first_bearing = 0.0;
  for (size_t i = 0; i < text.size(); ++i) {
    const FT_UInt glyph = FT_Get_Char_Index(face.get(), FT_ULong(static_cast<unsigned char>(text[i])));
    if (FT_Load_Glyph(face.get(), glyph, FT_LOAD_NO_SCALE) != 0) {
      throw InputError(loc, "cannot read the glyph of character " +
                                std::to_string(int(static_cast<unsigned char>(text[i]))) +
                                " in '" + path + "'");
    }
    const FT_GlyphSlot slot = face->glyph;
    if (i == 0) first_bearing = double(slot->metrics.horiBearingX);
    GlyphWalk walk = walk_outline(slot->outline);
    if (walk.cubic) {
      throw InputError(loc, "'" + path +
                                "' has cubic outlines (OpenType CFF): text objects take "
                                "TrueType fonts");
    }
    const auto place = [&](const Vec2& p) {
      return Vec2((p.x - first_bearing) * em + pen.x, p.y * em + pen.y);
    };
    for (scene::OutlinePiece& piece : walk.pieces) {
      piece = {place(piece.a), place(piece.b), place(piece.c)};
    }
    if (!walk.pieces.empty()) result.glyphs.push_back(std::move(walk.pieces));
    double advance = double(slot->metrics.horiAdvance);
    if (i + 1 < text.size() && FT_HAS_KERNING(face.get())) {
      const FT_UInt next =
          FT_Get_Char_Index(face.get(), FT_ULong(static_cast<unsigned char>(text[i + 1])));
      FT_Vector kerning{0, 0};
      FT_Get_Kerning(face.get(), glyph, next, FT_KERNING_UNSCALED, &kerning);
      advance += double(kerning.x);
    }
    pen += Vec2(advance * em, 0.0) + offset;
  }
  return result;
}

}  // namespace convray::font
