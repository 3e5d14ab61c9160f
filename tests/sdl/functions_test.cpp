// Built-in functions against values computed independently with <cmath> or by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::eval_float;
using core_testing::eval_string;
using core_testing::eval_vector;
using core_testing::expression_error;

const double kPi = std::acos(-1.0);

void expect_vec3(const Vector& v, double x, double y, double z, double tolerance = 1e-12) {
  EXPECT_EQ(v.size, 3);
  EXPECT_NEAR(v.v[0], x, tolerance);
  EXPECT_NEAR(v.v[1], y, tolerance);
  EXPECT_NEAR(v.v[2], z, tolerance);
}

TEST(Functions, FloatFunctionsOfOneArgument) {
  EXPECT_EQ(eval_float("abs(-2.5)"), 2.5);
  EXPECT_DOUBLE_EQ(eval_float("sqrt(2)"), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(eval_float("exp(1.5)"), std::exp(1.5));
  EXPECT_DOUBLE_EQ(eval_float("log(1000)"), 3.0);  // base 10
  EXPECT_DOUBLE_EQ(eval_float("ln(10)"), std::log(10.0));
  EXPECT_DOUBLE_EQ(eval_float("sin(0.5)"), std::sin(0.5));
  EXPECT_DOUBLE_EQ(eval_float("cos(0.5)"), std::cos(0.5));
  EXPECT_DOUBLE_EQ(eval_float("tan(0.5)"), std::tan(0.5));
  EXPECT_DOUBLE_EQ(eval_float("asin(0.5)"), std::asin(0.5));
  EXPECT_DOUBLE_EQ(eval_float("acos(0.5)"), std::acos(0.5));
  EXPECT_DOUBLE_EQ(eval_float("atan(0.5)"), std::atan(0.5));
  EXPECT_DOUBLE_EQ(eval_float("sinh(0.5)"), std::sinh(0.5));
  EXPECT_DOUBLE_EQ(eval_float("cosh(0.5)"), std::cosh(0.5));
  EXPECT_DOUBLE_EQ(eval_float("tanh(0.5)"), std::tanh(0.5));
  EXPECT_DOUBLE_EQ(eval_float("asinh(0.5)"), std::asinh(0.5));
  EXPECT_DOUBLE_EQ(eval_float("acosh(1.5)"), std::acosh(1.5));
  EXPECT_DOUBLE_EQ(eval_float("atanh(0.5)"), std::atanh(0.5));
  EXPECT_DOUBLE_EQ(eval_float("radians(180)"), kPi);
  EXPECT_DOUBLE_EQ(eval_float("degrees(pi / 2)"), 90.0);
  EXPECT_EQ(eval_float("sqr(-3)"), 9.0);
}

TEST(Functions, Rounding) {
  EXPECT_EQ(eval_float("int(2.7)"), 2.0);
  EXPECT_EQ(eval_float("int(-2.7)"), -2.0);  // toward zero
  EXPECT_EQ(eval_float("floor(-2.5)"), -3.0);
  EXPECT_EQ(eval_float("ceil(-2.5)"), -2.0);
  EXPECT_EQ(eval_float("ceil(2.1)"), 3.0);
}

TEST(Functions, FloatFunctionsOfSeveralArguments) {
  EXPECT_DOUBLE_EQ(eval_float("atan2(1, -1)"), std::atan2(1.0, -1.0));
  EXPECT_DOUBLE_EQ(eval_float("pow(2, 10)"), 1024.0);
  EXPECT_DOUBLE_EQ(eval_float("pow(-2, 3)"), -8.0);
  EXPECT_DOUBLE_EQ(eval_float("pow(2, 0.5)"), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(eval_float("mod(7.5, 2)"), 1.5);
  EXPECT_DOUBLE_EQ(eval_float("mod(-7.5, 2)"), std::fmod(-7.5, 2.0));
  EXPECT_EQ(eval_float("div(7, 2)"), 3.0);
  EXPECT_EQ(eval_float("div(-7, 2)"), -3.0);
  EXPECT_EQ(eval_float("min(3, 1, 2)"), 1.0);
  EXPECT_EQ(eval_float("max(3, 1, 2, 5)"), 5.0);
  EXPECT_EQ(eval_float("min(-1, 4)"), -1.0);
}

TEST(Functions, Select) {
  EXPECT_EQ(eval_float("select(-1, 10, 20)"), 10.0);
  EXPECT_EQ(eval_float("select(0, 10, 20)"), 20.0);
  EXPECT_EQ(eval_float("select(1, 10, 20)"), 20.0);
  EXPECT_EQ(eval_float("select(-1, 10, 20, 30)"), 10.0);
  EXPECT_EQ(eval_float("select(0, 10, 20, 30)"), 20.0);
  EXPECT_EQ(eval_float("select(2, 10, 20, 30)"), 30.0);
}

TEST(Functions, Bitwise) {
  EXPECT_EQ(eval_float("bitwise_and(12, 10)"), 8.0);
  EXPECT_EQ(eval_float("bitwise_or(12, 10)"), 14.0);
  EXPECT_EQ(eval_float("bitwise_xor(12, 10)"), 6.0);
  EXPECT_EQ(eval_float("bitwise_and(7, 6, 3)"), 2.0);
}

TEST(Functions, VectorFunctions) {
  EXPECT_DOUBLE_EQ(eval_float("vlength(<3, 4, 12>)"), 13.0);
  EXPECT_DOUBLE_EQ(eval_float("vlength(<3, 4>)"), 5.0);
  EXPECT_DOUBLE_EQ(eval_float("vdot(<1, 2, 3>, <4, -5, 6>)"), 4.0 - 10.0 + 18.0);
  expect_vec3(eval_vector("vcross(<1, 0, 0>, <0, 1, 0>)"), 0, 0, 1);
  expect_vec3(eval_vector("vcross(<1, 2, 3>, <4, 5, 6>)"), 2 * 6 - 3 * 5, 3 * 4 - 1 * 6,
              1 * 5 - 2 * 4);
  expect_vec3(eval_vector("vnormalize(<3, 0, 4>)"), 0.6, 0, 0.8);
  expect_vec3(eval_vector("vnormalize(2)"), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0),
              1 / std::sqrt(3.0));  // a float is <f, f, f>
}

TEST(Functions, VrotateFollowsPovRaysConvention) {
  // About y by 90 degrees, x goes to -z (POV-Ray's left-handed rotation).
  expect_vec3(eval_vector("vrotate(x, <0, 90, 0>)"), 0, 0, -1);
  expect_vec3(eval_vector("vrotate(y, <90, 0, 0>)"), 0, 0, 1);
  expect_vec3(eval_vector("vrotate(x, <0, 0, 90>)"), 0, 1, 0);
  // x first, then y, then z.
  const Vec3 expected = scene::Transform::rotation(Vec3(30, 40, 50)).vector(Vec3(1, 2, 3));
  expect_vec3(eval_vector("vrotate(<1, 2, 3>, <30, 40, 50>)"), expected.x, expected.y, expected.z);
}

TEST(Functions, VaxisRotateMatchesRotateAboutEachAxis) {
  expect_vec3(eval_vector("vaxis_rotate(x, y, 90)"), 0, 0, -1);
  for (const char* axis : {"x", "y", "z"}) {
    const std::string about = std::string(axis);
    const Vector a = eval_vector("vaxis_rotate(<1, 2, 3>, " + about + ", 33)");
    const Vector b = eval_vector("vrotate(<1, 2, 3>, 33 * " + about + ")");
    expect_vec3(a, b.v[0], b.v[1], b.v[2]);
  }
  // Any axis: the length and the component along the axis are kept.
  const Vector r = eval_vector("vaxis_rotate(<1, 2, 3>, <1, 1, 0>, 70)");
  EXPECT_NEAR(std::sqrt(r.v[0] * r.v[0] + r.v[1] * r.v[1] + r.v[2] * r.v[2]), std::sqrt(14.0),
              1e-12);
  EXPECT_NEAR((r.v[0] + r.v[1]) / std::sqrt(2.0), 3 / std::sqrt(2.0), 1e-12);
}

TEST(Functions, SeedAndRandAreDeterministicStreams) {
  const double a = eval_float("#declare S = seed(42); rand(S)");
  EXPECT_GE(a, 0.0);
  EXPECT_LT(a, 1.0);
  EXPECT_EQ(eval_float("#declare S = seed(42); rand(S)"), a);  // the same every run
  // A stream advances; two streams of the same seed give the same sequence.
  const double second = eval_float("#declare S = seed(42); #declare A = rand(S); rand(S)");
  EXPECT_NE(second, a);
  EXPECT_EQ(eval_float("#declare S = seed(42); #declare T = seed(42); "
                       "#declare A = rand(S); rand(T)"),
            a);
  EXPECT_NE(eval_float("#declare S = seed(43); rand(S)"), a);
  // Roughly uniform: the mean of 2000 draws.
  const double mean = eval_float(
      "#declare S = seed(7); #declare Sum = 0; #for (I, 1, 2000) #declare Sum = Sum + rand(S); "
      "#end Sum / 2000");
  EXPECT_NEAR(mean, 0.5, 0.03);
}

TEST(Functions, Strings) {
  EXPECT_EQ(eval_string("concat(\"a\", \"bc\", \"\", \"d\")"), "abcd");
  EXPECT_EQ(eval_string("str(3.14159, 0, 2)"), "3.14");
  EXPECT_EQ(eval_string("str(2.5, 6, 1)"), "   2.5");
  EXPECT_EQ(eval_string("str(2.5, -6, 1)"), "0002.5");
  EXPECT_EQ(eval_string("str(42, 0, 0)"), "42");
  EXPECT_EQ(eval_string("str(0.25, 0, -1)"), "0.25");
  EXPECT_EQ(eval_string("chr(65)"), "A");
  EXPECT_EQ(eval_string("substr(\"abcdef\", 2, 3)"), "bcd");
  EXPECT_EQ(eval_string("substr(\"abc\", 1, 0)"), "");
  EXPECT_EQ(eval_string("strupr(\"aBc1\")"), "ABC1");
  EXPECT_EQ(eval_string("strlwr(\"aBc1\")"), "abc1");
  EXPECT_EQ(eval_string("vstr(3, <1, 2.5, 3>, \", \", 0, 1)"), "1.0, 2.5, 3.0");
  EXPECT_EQ(eval_float("strlen(\"hello\")"), 5.0);
  EXPECT_EQ(eval_float("strlen(\"\")"), 0.0);
  EXPECT_EQ(eval_float("val(\"2.5e1\")"), 25.0);
  EXPECT_EQ(eval_float("val(\"abc\")"), 0.0);
  EXPECT_EQ(eval_float("asc(\"A\")"), 65.0);
  EXPECT_EQ(eval_float("strcmp(\"abc\", \"abd\")"), -1.0);
  EXPECT_EQ(eval_float("strcmp(\"abc\", \"abc\")"), 0.0);
  EXPECT_EQ(eval_float("strcmp(\"b\", \"a\")"), 1.0);
  EXPECT_EQ(eval_string("#declare N = 3; concat(\"n=\", str(N, 0, 0))"), "n=3");
}

TEST(Functions, Defined) {
  EXPECT_EQ(eval_float("#declare A = 1; defined(A)"), 1.0);
  EXPECT_EQ(eval_float("defined(Nothing)"), 0.0);
}

TEST(Functions, ArgumentCountsAreChecked) {
  core_testing::Failure failure = expression_error("sin(1, 2)");
  EXPECT_EQ(failure.first_line, "too many arguments: 'sin' takes 1");
  EXPECT_EQ(failure.loc.column, 8);  // at the extra argument
  failure = expression_error("atan2(1)");
  EXPECT_EQ(failure.first_line, "too few arguments: 'atan2' takes 2, found 1");
  failure = expression_error("max(1)");
  EXPECT_EQ(failure.first_line, "too few arguments: 'max' takes at least 2, found 1");
  failure = expression_error("sqrt 2");
  EXPECT_EQ(failure.first_line, "expected '(' after 'sqrt', found '2'");
}

TEST(Functions, MathErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"sqrt(-1)", "sqrt(): negative argument"},
      {"ln(0)", "ln(): argument not positive"},
      {"log(-2)", "log(): argument not positive"},
      {"asin(1.5)", "asin(): argument outside [-1, 1]"},
      {"acos(-2)", "acos(): argument outside [-1, 1]"},
      {"acosh(0.5)", "acosh(): argument below 1"},
      {"atanh(1)", "atanh(): argument outside (-1, 1)"},
      {"pow(0, -1)", "pow(): division by zero (0 to a negative power)"},
      {"pow(-2, 0.5)", "pow(): a negative number to a fractional power"},
      {"mod(1, 0)", "mod(): division by zero"},
      {"div(1, 0)", "div(): division by zero"},
      {"exp(1000)", "exp() gives a result that is not finite"},
      {"vnormalize(<0, 0, 0>)", "vnormalize(): the vector has length zero"},
      {"vaxis_rotate(x, <0, 0, 0>, 30)", "vaxis_rotate(): the axis has length zero"},
  };
  for (const auto& [text, message] : cases) {
    const core_testing::Failure failure = expression_error(text);
    EXPECT_EQ(failure.first_line, message) << text;
    EXPECT_EQ(failure.loc.column, 1) << text;  // at the function's name
  }
}

TEST(Functions, StringErrors) {
  EXPECT_EQ(expression_error("substr(\"abc\", 2, 5)").first_line,
            "substr(): characters 2 to 6 are outside the string (length 3)");
  EXPECT_EQ(expression_error("chr(0)").first_line, "chr(): the code must be 1 to 255");
  EXPECT_EQ(expression_error("strlen(3)").first_line,
            "expected a string in strlen(), found a float");
  EXPECT_EQ(expression_error("sin(\"a\")").first_line, "expected a float in sin(), found a string");
  EXPECT_EQ(expression_error("rand(5)").first_line,
            "rand() needs a stream made by seed(), found 5");
}

}  // namespace
}  // namespace convray::sdl
