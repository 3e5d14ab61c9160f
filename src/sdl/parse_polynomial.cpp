// POV-Ray's polynomial surfaces: `quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }`,
// `cubic { <20 coefficients> }`, `quartic { <35 coefficients> }` and
// `poly { ORDER, <coefficients> }`, all as scene::Polynomial (terms in POV-Ray's order).
#include <string>

#include "sdl/item_parsers.hpp"
#include "sdl/object_builder.hpp"

namespace convray::sdl::items {

namespace {

constexpr int kMaxOrder = 8;  // geometry's kMaxPolynomialDegree

int term_count(int order) { return (order + 1) * (order + 2) * (order + 3) / 6; }

// `< c1, c2, ... >` with exactly `count` floats (commas optional, as in vectors).
std::vector<double> coefficient_list(Parser& parser, const std::string& shape, int count,
                                     const SourceLoc& loc) {
  parser.expect("<", "before the coefficients of " + shape);
  std::vector<double> values;
  while (!parser.accept(">")) {
    if (int(values.size()) == count) {
      parser.fail_here(shape + " takes " + std::to_string(count) + " coefficients, found more");
    }
    values.push_back(parser.parse_float_in_angle_brackets());
    parser.accept_comma();
  }
  if (int(values.size()) != count) {
    parser.fail(loc, shape + " takes " + std::to_string(count) + " coefficients, found " +
                         std::to_string(values.size()));
  }
  return values;
}

scene::ObjectPtr finish(Block& block, scene::Polynomial polynomial, const SourceLoc& loc) {
  scene::Object object;
  object.shape = std::move(polynomial);
  object.loc = loc;
  return parse_modifiers(block, std::move(object));
}

}  // namespace

scene::ObjectPtr parse_polynomial(Parser& parser) {
  const std::string word = parser.peek().text;
  const SourceLoc loc = take_keyword(parser);
  Block block(parser, word, loc);
  scene::Polynomial polynomial;
  if (word == "quadric") {
    // A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J, into POV-Ray's order of
    // order 2: x², xy, xz, x, y², yz, y, z², z, 1.
    const Vec3 squares = vector_param(parser, "quadric's <A, B, C>");
    parser.accept_comma();
    const Vec3 mixed = vector_param(parser, "quadric's <D, E, F>");
    parser.accept_comma();
    const Vec3 linear = vector_param(parser, "quadric's <G, H, I>");
    parser.accept_comma();
    const double constant = float_param(parser, "quadric's J");
    polynomial.order = 2;
    polynomial.coefficients = {squares.x, mixed.x, mixed.y,  linear.x, squares.y,
                               mixed.z,   linear.y, squares.z, linear.z, constant};
    return finish(block, std::move(polynomial), loc);
  }
  if (word == "poly") {
    const SourceLoc order_at = parser.peek().loc;
    // `poly { 4 <...> }` (objects/primitiv.pov): the '<' starts the coefficients.
    polynomial.order = int(parser.parse_float_before_points());
    if (polynomial.order < 2 || polynomial.order > kMaxOrder) {
      parser.fail(order_at, "poly's order must be from 2 to " + std::to_string(kMaxOrder) +
                                " in convray (POV-Ray allows up to 15), found " +
                                std::to_string(polynomial.order));
    }
    parser.accept_comma();
  } else {
    polynomial.order = word == "cubic" ? 3 : 4;
  }
  polynomial.coefficients =
      coefficient_list(parser, word, term_count(polynomial.order), loc);
  return finish(block, std::move(polynomial), loc);
}

}  // namespace convray::sdl::items
