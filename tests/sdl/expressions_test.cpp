// Expressions, evaluated as parsed: operators and their precedence, float/vector promotion,
// vectors, colours, postfix components, constants.
#include <gtest/gtest.h>

#include <cmath>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::eval;
using core_testing::eval_float;
using core_testing::eval_string;
using core_testing::eval_vector;

void expect_vector(const Vector& v, std::initializer_list<double> components, bool color = false) {
  EXPECT_EQ(v.size, int(components.size()));
  EXPECT_EQ(v.color, color);
  size_t i = 0;
  for (double c : components) EXPECT_DOUBLE_EQ(v.v[i++], c) << "component " << i - 1;
}

TEST(Expressions, ArithmeticAndPrecedence) {
  EXPECT_EQ(eval_float("1+2*3"), 7.0);
  EXPECT_EQ(eval_float("(1+2)*3"), 9.0);
  EXPECT_EQ(eval_float("10-4-3"), 3.0);  // left to right
  EXPECT_EQ(eval_float("8/4/2"), 1.0);
  EXPECT_EQ(eval_float("2*3/4"), 1.5);
  EXPECT_EQ(eval_float("-2*3"), -6.0);
  EXPECT_EQ(eval_float("- -2"), 2.0);
  EXPECT_EQ(eval_float("+3"), 3.0);
  EXPECT_EQ(eval_float("1 - -1"), 2.0);
  EXPECT_EQ(eval_float("0.1 + 0.2"), 0.1 + 0.2);
}

TEST(Expressions, ComparisonsGiveZeroOrOne) {
  EXPECT_EQ(eval_float("1 < 2"), 1.0);
  EXPECT_EQ(eval_float("2 < 1"), 0.0);
  EXPECT_EQ(eval_float("2 <= 2"), 1.0);
  EXPECT_EQ(eval_float("3 >= 4"), 0.0);
  EXPECT_EQ(eval_float("3 > 2"), 1.0);
  EXPECT_EQ(eval_float("3 = 3"), 1.0);
  EXPECT_EQ(eval_float("3 != 3"), 0.0);
  // POV-Ray's = has a tolerance of 1e-10.
  EXPECT_EQ(eval_float("1 = 1 + 1e-11"), 1.0);
  EXPECT_EQ(eval_float("1 = 1 + 1e-9"), 0.0);
  EXPECT_EQ(eval_float("1 + 1 = 2"), 1.0);  // arithmetic binds tighter
}

TEST(Expressions, LogicOperators) {
  EXPECT_EQ(eval_float("1 & 0"), 0.0);
  EXPECT_EQ(eval_float("1 & 2"), 1.0);
  EXPECT_EQ(eval_float("0 | 0"), 0.0);
  EXPECT_EQ(eval_float("0 | 3"), 1.0);
  EXPECT_EQ(eval_float("!0"), 1.0);
  EXPECT_EQ(eval_float("!5"), 0.0);
  EXPECT_EQ(eval_float("!1e-11"), 1.0);  // within the tolerance of zero
  // | is looser than &, & looser than comparisons.
  EXPECT_EQ(eval_float("1 | 0 & 0"), 1.0);
  EXPECT_EQ(eval_float("1 < 2 & 3 < 4"), 1.0);
}

TEST(Expressions, Conditional) {
  EXPECT_EQ(eval_float("1 ? 2 : 3"), 2.0);
  EXPECT_EQ(eval_float("0 ? 2 : 3"), 3.0);
  EXPECT_EQ(eval_float("0 ? 1 : 0 ? 2 : 3"), 3.0);  // right-associative
  EXPECT_EQ(eval_float("2 > 1 ? 10 + 1 : 20"), 11.0);
  // The branch not taken may divide by zero (POV-Ray evaluates both).
  EXPECT_EQ(eval_float("#declare N = 0; (N = 0 ? 0 : 1 / N)"), 0.0);
  EXPECT_EQ(eval_float("0 & 1/0"), 0.0);
  EXPECT_EQ(eval_float("1 | sqrt(-1)"), 1.0);
  expect_vector(eval_vector("1 ? <1, 2> : 3"), {1, 2});
}

TEST(Expressions, Vectors) {
  expect_vector(eval_vector("<1, 2, 3>"), {1, 2, 3});
  expect_vector(eval_vector("<1, 2>"), {1, 2});
  expect_vector(eval_vector("<1, 2, 3, 4, 5>"), {1, 2, 3, 4, 5});
  expect_vector(eval_vector("<1+1, 2*3, -1>"), {2, 6, -1});
  // Commas between components are optional, as in POV-Ray (woods.inc relies on it).
  expect_vector(eval_vector("< -1 0 0 >"), {-1, 0, 0});
  // Inside < >, '>' ends the vector: comparisons need parentheses.
  expect_vector(eval_vector("<(2 > 1), (1 >= 2), 1 < 2>"), {1, 0, 1});
}

TEST(Expressions, VectorArithmeticPromotesFloats) {
  expect_vector(eval_vector("<1, 2, 3> * 2"), {2, 4, 6});
  expect_vector(eval_vector("2 * <1, 2, 3>"), {2, 4, 6});
  expect_vector(eval_vector("<1, 2, 3> + 1"), {2, 3, 4});
  expect_vector(eval_vector("1 - <1, 2, 3>"), {0, -1, -2});
  expect_vector(eval_vector("<1, 2, 3> * <2, 3, 4>"), {2, 6, 12});
  expect_vector(eval_vector("<2, 4, 8> / <2, 2, 2>"), {1, 2, 4});
  expect_vector(eval_vector("1 / <1, 2, 4>"), {1, 0.5, 0.25});
  expect_vector(eval_vector("-<1, -2, 3>"), {-1, 2, -3});
  // Sizes mix by padding with zeros.
  expect_vector(eval_vector("<1, 2> + <1, 1, 1>"), {2, 3, 1});
  expect_vector(eval_vector("x + 2*y - z"), {1, 2, -1});
}

TEST(Expressions, PostfixComponents) {
  EXPECT_EQ(eval_float("<1, 2, 3>.x"), 1.0);
  EXPECT_EQ(eval_float("<1, 2, 3>.y"), 2.0);
  EXPECT_EQ(eval_float("<1, 2, 3>.z"), 3.0);
  EXPECT_EQ(eval_float("<1, 2, 3, 4>.t"), 4.0);
  EXPECT_EQ(eval_float("<5, 6>.u"), 5.0);
  EXPECT_EQ(eval_float("<5, 6>.v"), 6.0);
  EXPECT_EQ(eval_float("(rgbft <1, 2, 3, 4, 5>).red"), 1.0);
  EXPECT_EQ(eval_float("(rgbft <1, 2, 3, 4, 5>).green"), 2.0);
  EXPECT_EQ(eval_float("(rgbft <1, 2, 3, 4, 5>).blue"), 3.0);
  EXPECT_EQ(eval_float("(rgbft <1, 2, 3, 4, 5>).filter"), 4.0);
  EXPECT_EQ(eval_float("(rgbft <1, 2, 3, 4, 5>).transmit"), 5.0);
  EXPECT_DOUBLE_EQ(eval_float("(rgb <1, 0.5, 0.25>).gray"), 0.297 + 0.589 * 0.5 + 0.114 * 0.25);
  EXPECT_EQ(eval_float("(<1, 2, 3> * 2).z"), 6.0);
  EXPECT_EQ(eval_float("#declare V = <7, 8, 9>; V.y + 1"), 9.0);
  EXPECT_EQ(eval_float("<1, 2, 3>.t"), 0.0);  // past the size: zero, as POV-Ray pads
}

TEST(Expressions, Constants) {
  EXPECT_DOUBLE_EQ(eval_float("pi"), std::acos(-1.0));
  EXPECT_DOUBLE_EQ(eval_float("tau"), 2.0 * std::acos(-1.0));
  for (const char* yes : {"true", "yes", "on"}) EXPECT_EQ(eval_float(yes), 1.0) << yes;
  for (const char* no : {"false", "no", "off"}) EXPECT_EQ(eval_float(no), 0.0) << no;
  expect_vector(eval_vector("x"), {1, 0, 0});
  expect_vector(eval_vector("y"), {0, 1, 0});
  expect_vector(eval_vector("z"), {0, 0, 1});
  expect_vector(eval_vector("t"), {0, 0, 0, 1});
  expect_vector(eval_vector("u"), {1, 0});
  expect_vector(eval_vector("v"), {0, 1});
  EXPECT_EQ(eval_float("version"), 3.7);
  EXPECT_EQ(eval_float("#version 3.5; version"), 3.5);
}

TEST(Expressions, ConstantsFromTheOptions) {
  ParseOptions options;
  options.clock = 0.25;
  options.clock_delta = 0.05;
  options.clock_on = true;
  options.frame_number = 6;
  options.initial_frame = 1;
  options.final_frame = 21;
  options.initial_clock = 0.0;
  options.final_clock = 1.0;
  options.image_width = 640;
  options.image_height = 480;
  EXPECT_EQ(eval_float("clock", options), 0.25);
  EXPECT_EQ(eval_float("clock_delta", options), 0.05);
  EXPECT_EQ(eval_float("clock_on", options), 1.0);
  EXPECT_EQ(eval_float("frame_number", options), 6.0);
  EXPECT_EQ(eval_float("initial_frame", options), 1.0);
  EXPECT_EQ(eval_float("final_frame", options), 21.0);
  EXPECT_EQ(eval_float("initial_clock", options), 0.0);
  EXPECT_EQ(eval_float("final_clock", options), 1.0);
  EXPECT_EQ(eval_float("image_width", options), 640.0);
  EXPECT_EQ(eval_float("image_height", options), 480.0);
  EXPECT_EQ(eval_float("clock"), 0.0);
  options.declares = {{"Quality", 9.0}};
  EXPECT_EQ(eval_float("Quality + 1", options), 10.0);
}

TEST(Expressions, Colors) {
  expect_vector(eval_vector("rgb <1, 0.5, 0>"), {1, 0.5, 0, 0, 0}, true);
  expect_vector(eval_vector("rgb 0.5"), {0.5, 0.5, 0.5, 0, 0}, true);
  expect_vector(eval_vector("rgbf <1, 0, 0, 0.5>"), {1, 0, 0, 0.5, 0}, true);
  expect_vector(eval_vector("rgbf 1"), {1, 1, 1, 1, 0}, true);
  expect_vector(eval_vector("rgbt <1, 0, 0, 0.5>"), {1, 0, 0, 0, 0.5}, true);
  expect_vector(eval_vector("rgbft <1, 0, 0, 0.25, 0.5>"), {1, 0, 0, 0.25, 0.5}, true);
  expect_vector(eval_vector("color rgb <1, 0, 0>"), {1, 0, 0, 0, 0}, true);
  expect_vector(eval_vector("colour rgb x"), {1, 0, 0, 0, 0}, true);
  expect_vector(eval_vector("color red 1 green 0.5"), {1, 0.5, 0, 0, 0}, true);
  expect_vector(eval_vector("color red 0.25 blue 1 filter 0.5 transmit 0.25"),
                {0.25, 0, 1, 0.5, 0.25}, true);
  expect_vector(eval_vector("rgb <1, 0, 0> transmit 0.5"), {1, 0, 0, 0, 0.5}, true);
  expect_vector(eval_vector("color <1, 0, 0, 0.5>"), {1, 0, 0, 0.5, 0}, true);
  expect_vector(eval_vector("color 0.5"), {0.5, 0.5, 0.5, 0, 0}, true);
  expect_vector(eval_vector("rgb <1, 1, 1> * 0.5"), {0.5, 0.5, 0.5, 0, 0}, true);
}

TEST(Expressions, ColorIdentifiersTakeModifiers) {
  expect_vector(eval_vector("#declare Red = rgb <1, 0, 0>; Red filter 0.5"), {1, 0, 0, 0.5, 0},
                true);
  expect_vector(eval_vector("#declare Red = rgb <1, 0, 0>; color Red transmit 0.5 green 1"),
                {1, 1, 0, 0, 0.5}, true);
  // Colour arithmetic keeps the colour, float promotion covers all five components.
  expect_vector(eval_vector("#declare White = rgb 1; White * 0.25"), {0.25, 0.25, 0.25, 0, 0},
                true);
  expect_vector(eval_vector("(rgb 1) + 0.5"), {1.5, 1.5, 1.5, 0.5, 0.5}, true);
  // A keyword's operand is the whole additive expression after it.
  expect_vector(eval_vector("rgb 1 + 0.5"), {1.5, 1.5, 1.5, 0, 0}, true);
  expect_vector(eval_vector("rgb <1, 2, 3>.y"), {2, 2, 2, 0, 0}, true);  // rgb (<1, 2, 3>.y)
}

TEST(Expressions, SrgbIsDecodedToLinear) {
  const auto linear = [](double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  expect_vector(eval_vector("srgb <1, 0.5, 0.02>"), {1, linear(0.5), linear(0.02), 0, 0}, true);
  expect_vector(eval_vector("srgbf <0.5, 0.5, 0.5, 0.5>"),
                {linear(0.5), linear(0.5), linear(0.5), 0.5, 0}, true);
  expect_vector(eval_vector("srgbt <0.5, 0, 0, 0.5>"), {linear(0.5), 0, 0, 0, 0.5}, true);
  expect_vector(eval_vector("srgbft <0.5, 0, 0, 0.25, 0.5>"), {linear(0.5), 0, 0, 0.25, 0.5}, true);
}

TEST(Expressions, ParserApiConvertsValues) {
  Parser vectors("test.pov", "2, <1, 2, 3>, <4, 5>", {});
  EXPECT_EQ(vectors.parse_vector(), Vec3(2.0));  // a float f is <f, f, f>
  vectors.accept_comma();
  EXPECT_EQ(vectors.parse_vector(), Vec3(1, 2, 3));
  vectors.accept_comma();
  EXPECT_EQ(vectors.parse_vector(), Vec3(4, 5, 0));

  Parser colors("test.pov", "0.5, <1, 0, 0> rgbt <0, 1, 0, 0.5>, <1, 1, 1> filter 0.25", {});
  scene::Color c = colors.parse_color();
  EXPECT_EQ(c.rgb, Vec3(0.5));
  EXPECT_EQ(c.filter, 0.0);
  colors.accept_comma();
  c = colors.parse_color();
  EXPECT_EQ(c.rgb, Vec3(1, 0, 0));
  EXPECT_EQ(c.transmit, 0.0);
  c = colors.parse_color();
  EXPECT_EQ(c.rgb, Vec3(0, 1, 0));
  EXPECT_EQ(c.transmit, 0.5);
  colors.accept_comma();
  c = colors.parse_color();
  EXPECT_EQ(c.rgb, Vec3(1, 1, 1));
  EXPECT_EQ(c.filter, 0.25);

  Parser numbers("test.pov", "1+2*3 7 2.9999999999999, -4.5 concat(\"a\", \"b\")", {});
  EXPECT_EQ(numbers.parse_float(), 7.0);
  EXPECT_EQ(numbers.parse_int(), 7);
  EXPECT_EQ(numbers.parse_int(), 3);  // a rounding error below 3 is 3
  numbers.accept_comma();
  EXPECT_EQ(numbers.parse_int(), -4);  // truncated, as POV-Ray does
  EXPECT_EQ(numbers.parse_string(), "ab");
  EXPECT_EQ(numbers.peek().kind, Token::Kind::end);
}

TEST(Expressions, CommasAreOptionalBetweenVectors) {
  // POV-Ray compares only floats: after a vector, '<' starts the next one.
  Parser parser("test.pov", "<-1, -2, -3> <1, 2, 3> <4 5 6>", {});
  EXPECT_EQ(parser.parse_vector(), Vec3(-1, -2, -3));
  EXPECT_EQ(parser.parse_vector(), Vec3(1, 2, 3));
  EXPECT_EQ(parser.parse_vector(), Vec3(4, 5, 6));
  EXPECT_EQ(parser.peek().kind, Token::Kind::end);
}

TEST(Expressions, FloatsInsideAnItemsAngleBrackets) {
  // matrix <..., V.z> : the '>' ends the last value instead of comparing.
  Parser parser("test.pov", "#declare V = <1, 2, 3>; < 1, V.z > 1", {});
  EXPECT_TRUE(parser.accept("<"));
  EXPECT_EQ(parser.parse_float_in_angle_brackets(), 1.0);
  parser.accept_comma();
  EXPECT_EQ(parser.parse_float_in_angle_brackets(), 3.0);
  EXPECT_TRUE(parser.accept(">"));
  EXPECT_EQ(parser.parse_float(), 1.0);
}

TEST(Expressions, TokensApi) {
  Parser parser("test.pov", "sphere { <1, 2, 3>, 0.5 } \"str\" Name", {});
  EXPECT_TRUE(parser.at("sphere"));
  EXPECT_FALSE(parser.at("box"));
  EXPECT_EQ(parser.peek().kind, Token::Kind::keyword);
  EXPECT_EQ(parser.peek().loc.str(), "test.pov:1:1");
  EXPECT_TRUE(parser.accept("sphere"));
  const Token brace = parser.expect("{", "sphere");
  EXPECT_EQ(brace.text, "{");
  EXPECT_EQ(brace.loc.column, 8);
  EXPECT_EQ(parser.parse_vector(), Vec3(1, 2, 3));
  parser.accept_comma();
  EXPECT_EQ(parser.parse_float(), 0.5);
  EXPECT_FALSE(parser.accept(","));
  EXPECT_EQ(parser.next().text, "}");
  EXPECT_EQ(parser.peek().kind, Token::Kind::string);
  EXPECT_EQ(parser.next().text, "str");
  EXPECT_EQ(parser.peek().kind, Token::Kind::identifier);
  EXPECT_EQ(parser.peek_declared(), nullptr);
  EXPECT_FALSE(parser.at("Name"));  // at() is for keywords and symbols
  EXPECT_EQ(parser.next().text, "Name");
  EXPECT_EQ(parser.peek().kind, Token::Kind::end);
  EXPECT_EQ(parser.next().kind, Token::Kind::end);  // the end stays
}

TEST(Expressions, PeekDeclaredSeesIdentifiers) {
  Parser parser("test.pov", "#declare Size = 2; Size Other", {});
  const Value* size = parser.peek_declared();
  ASSERT_NE(size, nullptr);
  EXPECT_EQ(*size->get<double>(), 2.0);
  EXPECT_EQ(size->loc.str(), "test.pov:1:10");  // where it was declared
  parser.next();
  EXPECT_EQ(parser.peek_declared(), nullptr);
}

TEST(Expressions, IdentifiersOfEveryType) {
  EXPECT_EQ(eval_float("#declare A = 2; #local B = A * 3; A + B"), 8.0);
  EXPECT_EQ(eval_string("#declare S = \"text\"; S"), "text");
  expect_vector(eval_vector("#declare V = <1, 2, 3>; V * 2"), {2, 4, 6});
}

}  // namespace
}  // namespace convray::sdl
