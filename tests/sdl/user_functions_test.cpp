// User-defined functions compiled where they are declared (sdl/function_compiler.cpp,
// scene/function.hpp): values against the same arithmetic done here, and the rules of
// POV-Ray's function language (identifiers read when the function is declared).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sdl/core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::eval_float;

TEST(UserFunctions, OperatorsFollowThePrecedenceOfExpressions) {
  const double x = 1.5, y = -2.0, z = 0.25;
  const std::string call = " F(1.5, -2, 0.25)";
  EXPECT_DOUBLE_EQ(eval_float("#declare F = function { x + y * z - x / y }" + call),
                   x + y * z - x / y);
  EXPECT_DOUBLE_EQ(eval_float("#declare F = function { -x * -(y - z) }" + call), -x * -(y - z));
  EXPECT_EQ(eval_float("#declare F = function { x > y & y < z }" + call), 1.0);
  EXPECT_EQ(eval_float("#declare F = function { x < y | z >= 1 }" + call), 0.0);
  EXPECT_EQ(eval_float("#declare F = function { !(x = 1.5) + (y != 3) }" + call), 1.0);
  EXPECT_DOUBLE_EQ(eval_float("#declare F = function { x < 0 ? y : z * 2 }" + call), z * 2);
}

TEST(UserFunctions, BuiltInFloatFunctions) {
  const double a = 0.3, b = 2.5;
  const std::string call = " F(0.3, 2.5)";
  const auto f = [&](const std::string& body) {
    return eval_float("#declare F = function (a, b) { " + body + " }" + call);
  };
  EXPECT_DOUBLE_EQ(f("sin(a) * cos(b) + tan(a)"), std::sin(a) * std::cos(b) + std::tan(a));
  EXPECT_DOUBLE_EQ(f("atan2(a, b) + asin(a) + acos(a)"),
                   std::atan2(a, b) + std::asin(a) + std::acos(a));
  EXPECT_DOUBLE_EQ(f("sqrt(b) + exp(a) + ln(b) + log(b)"),
                   std::sqrt(b) + std::exp(a) + std::log(b) + std::log10(b));
  EXPECT_DOUBLE_EQ(f("pow(b, a) + mod(7.5, b + 0.5) + div(7, b)"),
                   std::pow(b, a) + std::fmod(7.5, b + 0.5) + std::trunc(7 / b));
  EXPECT_DOUBLE_EQ(f("min(a, b, -1) + max(a, b) + abs(-b) + floor(b) + ceil(a) + int(-b)"),
                   -1 + b + b + 2 + 1 - 2);
  EXPECT_DOUBLE_EQ(f("select(a - 1, a, b) + select(0, 1, 10, 100) + radians(180)"),
                   a + 10 + std::acos(-1.0));
}

TEST(UserFunctions, CallsOtherFunctionsAndFunctionsIncludedFromPovRay) {
  EXPECT_DOUBLE_EQ(eval_float("#declare Sq = function (t) { t * t } "
                              "#declare F = function { Sq(x) + Sq(y) + Sq(z) } F(1, 2, 3)"),
                   14.0);
  // functions.inc: f_r, f_sphere, f_rounded_box as the reference manual describes them.
  const std::string inc = "#include \"functions.inc\" ";
  EXPECT_DOUBLE_EQ(eval_float(inc + "f_r(1, 2, 2)"), 3.0);
  EXPECT_DOUBLE_EQ(eval_float(inc + "f_sphere(0, 3, 4, 2)"), 3.0);
  // A box of half sizes 0.5 with corners rounded by 0.05: 0 on a face, -0.2 inside at 0.3
  // from the centre along x (0.2 from the face), and at a corner the distance to the sphere
  // of radius 0.05 about the corner's inner centre.
  EXPECT_NEAR(eval_float(inc + "f_rounded_box(0.5, 0, 0, 0.05, 0.5, 0.5, 0.5)"), 0.0, 1e-12);
  EXPECT_NEAR(eval_float(inc + "f_rounded_box(0.1, 0, 0, 0.05, 0.5, 0.5, 0.5)"), -0.4, 1e-12);
  const double corner = std::sqrt(3.0) * (0.6 - 0.45) - 0.05;
  EXPECT_NEAR(eval_float(inc + "f_rounded_box(0.6, 0.6, 0.6, 0.05, 0.5, 0.5, 0.5)"), corner,
              1e-12);
}

TEST(UserFunctions, IdentifiersAreReadWhereTheFunctionIsDeclared) {
  EXPECT_EQ(eval_float("#declare A = 2; #declare F = function { x * A } #declare A = 3; "
                       "F(5, 0, 0)"),
            10.0);
  EXPECT_EQ(eval_float("#declare V = <1, 7, 3>; #declare F = function { V.y + pi * 0 } "
                       "F(0, 0, 0)"),
            7.0);
  // Parameters hide declared identifiers of the same name.
  EXPECT_EQ(eval_float("#declare a = 100; #declare F = function (a) { a + 1 } F(1)"), 2.0);
}

TEST(UserFunctions, WhatCannotBeEvaluatedYetFailsWhereItIsUsed) {
  // Declaring is fine (functions.inc declares pattern functions); calling names the feature.
  const auto error = core_testing::expression_error(
      "#declare P = function { pattern { crackle } } P(1, 2, 3)");
  EXPECT_NE(error.first_line.find("'crackle' is not supported yet by convray (at test.pov:1:35)"),
            std::string::npos)
      << error.first_line;
  EXPECT_NE(error.first_line.find("'P', declared at test.pov:1:14"), std::string::npos)
      << error.first_line;
  EXPECT_EQ(core_testing::expression_error("#declare F = function { x + q } F(1, 2, 3)")
                .first_line.rfind("undeclared identifier 'q'", 0),
            0u);
}

TEST(UserFunctions, PigmentAndPatternFunctions) {
  // A pigment function gives the colour (POV-Ray's eval_pigment in functions.inc does this).
  EXPECT_DOUBLE_EQ(eval_float("#declare P = function { pigment { rgb <0.2, 0.4, 0.6> } } "
                              "P(1, 2, 3).green"),
                   0.4);
  // gradient x through a black-to-white map: the fractional part of x, in every channel.
  const std::string gradient =
      "#declare P = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } "
      "} } ";
  EXPECT_NEAR(eval_float(gradient + "P(2.25, 7, 7).red"), 0.25, 1e-12);
  EXPECT_NEAR(eval_float(gradient + "#declare F = function { P(x, 0, 0).green * 4 } F(0.75, 0, 0)"),
              0.375 * 4, 1e-12);
  // A pattern function is the pattern's value: gradient x wraps, scale applies.
  const std::string pattern = "#declare G = function { pattern { gradient x scale 2 } } ";
  EXPECT_NEAR(eval_float(pattern + "G(0.5, 0, 0)"), 0.25, 1e-12);
  EXPECT_NEAR(eval_float(pattern + "G(3.5, 0, 0)"), 0.75, 1e-12);
  EXPECT_NE(core_testing::expression_error(gradient + "#declare F = function { P(x, y, z) } 1")
                .first_line.find("gives a colour: pick a component"),
            std::string::npos);
}

}  // namespace
}  // namespace convray::sdl
