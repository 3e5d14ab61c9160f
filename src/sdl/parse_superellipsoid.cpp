// `superellipsoid { <e, n> [modifiers] }`: POV-Ray's superquadric ellipsoid in the box
// [-1, 1]^3 (geometry/superellipsoid.hpp has the surface).
#include <cmath>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

scene::ObjectPtr parse_superellipsoid(Parser& parser) {
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, "superellipsoid", loc);
  const SourceLoc at = parser.peek().loc;
  const Vec3 exponents = vector_param(parser, "the exponents <e, n>");
  scene::Superellipsoid shape{exponents.x, exponents.y};
  // POV-Ray draws something for exponents <= 0 without a word; what is not documented, so
  // convray refuses them rather than guess.
  if (!(shape.e > 0.0) || !(shape.n > 0.0) || !std::isfinite(shape.e + shape.n)) {
    parser.fail(at, "superellipsoid: the exponents <e, n> must be positive, found <" +
                        number_text(shape.e) + ", " + number_text(shape.n) + ">");
  }
  scene::Object object;
  object.shape = shape;
  object.loc = loc;
  return parse_modifiers(block, std::move(object));
}

}  // namespace convray::sdl::items
