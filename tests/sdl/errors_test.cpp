// Every error of the parser core says what is wrong on its first line, then shows the source
// line with a caret under the column; the location is the offending token's.
#include <gtest/gtest.h>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::expression_error;
using core_testing::Failure;
using core_testing::scene_error;

::testing::AssertionResult fails_at(const Failure& failure, int line, int column,
                                    const std::string& first_line) {
  if (failure.loc.line == line && failure.loc.column == column &&
      failure.first_line == first_line) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "got " << failure.loc.line << ":" << failure.loc.column << " '" << failure.first_line
         << "', expected " << line << ":" << column << " '" << first_line << "'";
}

TEST(Errors, MessageShowsTheLineAndACaret) {
  try {
    Parser parser("scene.pov", "#declare A = 1;\n\tsphere { 0, 1 } 1 + foo\n", {});
    parser.parse_float();
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.loc().str(), "scene.pov:2:2");
  }
  try {
    Parser parser("scene.pov", "#declare A = 1;\n\t1 + sqroot\n", {});
    parser.parse_float();
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "scene.pov:2:6: undeclared identifier 'sqroot' (did you mean 'sqrt'?)\n"
              "    \t1 + sqroot\n"
              "    \t    ^");
    EXPECT_EQ(error.loc().line, 2);
    EXPECT_EQ(error.loc().column, 6);
  }
}

TEST(Errors, UndeclaredIdentifiersSuggestClosestNames) {
  EXPECT_TRUE(fails_at(expression_error("#declare Count_Max = 1;\n2 * count_max"), 2, 5,
                       "undeclared identifier 'count_max' (did you mean 'Count_Max'?)"));
  // Reserved words of items are not values.
  EXPECT_TRUE(fails_at(expression_error("2 * radius"), 1, 5, "expected a value, found 'radius'"));
  EXPECT_TRUE(fails_at(expression_error("#declare Thing_Size = 1;\nThing_Sise"), 2, 1,
                       "undeclared identifier 'Thing_Sise' (did you mean 'Thing_Size'?)"));
  EXPECT_TRUE(fails_at(expression_error("sqrtt(4)"), 1, 1,
                       "undeclared identifier 'sqrtt' (did you mean 'sqrt'?)"));
  EXPECT_TRUE(fails_at(expression_error("Zebra"), 1, 1, "undeclared identifier 'Zebra'"));
  Parser parser("test.pov", "#declare Count_Max = 3;", {});
  parser.parse_scene();
  EXPECT_EQ(parser.did_you_mean("count_max"), " (did you mean 'Count_Max'?)");
  EXPECT_EQ(parser.did_you_mean("spehre"), " (did you mean 'sphere'?)");
  EXPECT_EQ(parser.did_you_mean("completely_different"), "");
}

TEST(Errors, UnknownDirectives) {
  EXPECT_TRUE(fails_at(scene_error("\n  #delcare A = 1;"), 2, 3,
                       "unknown directive '#delcare' (did you mean '#declare'?)"));
  EXPECT_TRUE(fails_at(scene_error("#frobnicate"), 1, 1, "unknown directive '#frobnicate'"));
  // A '#' with no name is passed over, as POV-Ray does, with a warning.
  const ParseResult stray = core_testing::run("#declare V = <0, 2, 0>; # \n#declare W = 1;\n#version 3.7;");
  ASSERT_EQ(stray.warnings.size(), 1u);
  EXPECT_EQ(stray.warnings[0].substr(0, stray.warnings[0].find('\n')),
            "test.pov:1:25: '#' without a directive name, ignored");
  // Without an output folder (a parse without a render) no file may be written.
  EXPECT_TRUE(fails_at(scene_error("#fopen F \"x.txt\" write"), 1, 10,
                       "#fopen 'x.txt' for writing: this command writes no files"));
  EXPECT_TRUE(fails_at(scene_error("#fopen F \"x.txt\" wrote"), 1, 18,
                       "expected read, write or append after #fopen's file name, found 'wrote'"));
}

TEST(Errors, DeclarationSyntax) {
  EXPECT_TRUE(fails_at(scene_error("#declare sphere = 1;"), 1, 10,
                       "'sphere' is a reserved word and cannot be used as an identifier after "
                       "#declare"));
  EXPECT_TRUE(fails_at(scene_error("#local 3 = 1;"), 1, 8,
                       "expected an identifier after #local, found '3'"));
  EXPECT_TRUE(
      fails_at(scene_error("#declare A 1;"), 1, 12, "expected '=' after #declare A, found '1'"));
  EXPECT_TRUE(fails_at(scene_error("#declare A = ;"), 1, 14,
                       "expected a value (a number, vector, colour, string or identifier), found "
                       "';'"));
  EXPECT_TRUE(fails_at(scene_error("#declare A ="), 1, 13,
                       "expected a value (a number, vector, colour, string or identifier), found "
                       "the end of the file"));
}

TEST(Errors, Parentheses) {
  EXPECT_TRUE(fails_at(expression_error("(1 + 2"), 1, 7,
                       "expected ')' to close the '(' at 1:1, found the end of the file"));
  EXPECT_TRUE(fails_at(expression_error("2 * (1 + 2 ]"), 1, 12,
                       "expected ')' to close the '(' at 1:5, found ']'"));
  EXPECT_TRUE(fails_at(expression_error("1 ? 2 3"), 1, 7,
                       "expected ':' in the conditional expression 'a ? b : c', found '3'"));
}

TEST(Errors, Vectors) {
  EXPECT_TRUE(fails_at(expression_error("<1, 2, 3"), 1, 9,
                       "expected ',' or '>' in the vector opened at 1:1, found the end of the "
                       "file"));
  EXPECT_TRUE(
      fails_at(expression_error("<1, 2, 3, 4, 5, 6>"), 1, 17, "a vector has at most 5 components"));
  EXPECT_TRUE(fails_at(expression_error("<1>"), 1, 1, "a vector needs at least 2 components"));
  EXPECT_TRUE(fails_at(expression_error("<1, <2, 3>>"), 1, 5,
                       "expected a float as a vector component, found a vector"));
  EXPECT_TRUE(fails_at(expression_error("<1, 2>.w"), 1, 8,
                       "expected a component after '.' (x, y, z, t, u, v, red, green, blue, "
                       "filter, transmit, gray), found 'w'"));
  EXPECT_TRUE(fails_at(expression_error("\"s\".x"), 1, 4,
                       "'.' needs a vector or a colour, found a string"));
}

TEST(Errors, DivisionByZero) {
  EXPECT_TRUE(fails_at(expression_error("1 + 2 / 0"), 1, 7, "division by zero"));
  EXPECT_TRUE(
      fails_at(expression_error("<1, 2, 3> / <1, 0, 1>"), 1, 11, "division by zero (component 2)"));
  EXPECT_TRUE(fails_at(expression_error("#declare Z = 0;\n<1, 2> / Z"), 2, 8,
                       "division by zero (component 1)"));
}

TEST(Errors, Overflow) {
  EXPECT_TRUE(fails_at(expression_error("1e308 * 10"), 1, 7, "overflow: the result is not finite"));
  EXPECT_TRUE(fails_at(expression_error("<1, 1e308> + <0, 1e308>"), 1, 12,
                       "overflow: the result is not finite"));
  EXPECT_EQ(core_testing::eval_float("0 ? 1e308 * 10 : 2"), 2.0);
}

TEST(Errors, TypeMismatches) {
  EXPECT_TRUE(
      fails_at(expression_error("\"a\" + 1"), 1, 5, "'+' needs floats or vectors, found a string"));
  EXPECT_TRUE(
      fails_at(expression_error("1 < <1, 2>"), 1, 3, "'<' compares floats, found a vector"));
  EXPECT_TRUE(
      fails_at(expression_error("1 = <1, 2>"), 1, 3, "'=' compares floats, found a vector"));
  EXPECT_TRUE(fails_at(expression_error("-\"a\""), 1, 1,
                       "unary '-' needs a float or a vector, found a string"));
  EXPECT_TRUE(
      fails_at(expression_error("!<1, 2>"), 1, 1, "expected a float after '!', found a vector"));
  EXPECT_TRUE(fails_at(expression_error("<1, 2> ? 1 : 2"), 1, 8,
                       "expected a float before '?', found a vector"));
  EXPECT_TRUE(fails_at(expression_error("sphere"), 1, 1, "expected a value, found 'sphere'"));
  EXPECT_TRUE(fails_at(expression_error("1 + trace(A, x, y)"), 1, 5,
                       "'trace' is not supported yet by convray"));
  Parser parser("test.pov", "  <1, 2, 3>", {});
  try {
    parser.parse_float();
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(core_testing::to_failure(error).first_line, "expected a float, found a vector");
    EXPECT_EQ(error.loc().column, 3);
  }
  EXPECT_TRUE(fails_at(scene_error("#declare T = texture { pigment { rgb 1 } }\n"
                                   "#declare A = T + 1;"),
                       2, 16, "'+' needs floats or vectors, found a texture"));
}

TEST(Errors, ExpectNamesWhatWasExpected) {
  Parser in_sphere("test.pov", "sphere 1", {});
  in_sphere.accept("sphere");
  try {
    in_sphere.expect("{", "sphere");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(core_testing::to_failure(error).first_line, "expected '{' in sphere, found '1'");
  }
  Parser closing("test.pov", "texure", {});
  try {
    closing.expect("}", "to close sphere (opened at 2:1)");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "test.pov:1:1: expected '}' to close sphere (opened at 2:1), found 'texure'\n"
              "    texure\n"
              "    ^");
  }
}

TEST(Errors, FailAndWarnFromItemParsers) {
  Parser parser("scene.pov", "a\n  bc d", {});
  parser.next();
  try {
    parser.fail_here("something about bc");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "scene.pov:2:3: something about bc\n      bc d\n      ^");
  }
  parser.warn(parser.peek().loc, "a warning");
  ASSERT_EQ(parser.warnings().size(), 1u);
  EXPECT_EQ(parser.warnings()[0], "scene.pov:2:3: a warning\n      bc d\n      ^");
  try {
    parser.fail(SourceLoc{"elsewhere.obj", 0, 0}, "not in a scene file");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "elsewhere.obj: not in a scene file");
  }
}

TEST(Errors, NestingDepthIsLimitedNotTheStack) {
  const std::string deep(1000, '(');
  Failure failure = expression_error(deep + "1" + std::string(1000, ')'));
  EXPECT_EQ(failure.first_line,
            "nested more than 512 levels deep (expressions, items or directives)");
  EXPECT_EQ(failure.loc.line, 1);
  // Vectors, function calls, conditionals and macro arguments count the same way.
  std::string vectors;
  for (int i = 0; i < 2000; ++i) vectors += "<1, ";
  EXPECT_EQ(expression_error(vectors).first_line, failure.first_line);
  std::string calls;
  for (int i = 0; i < 2000; ++i) calls += "abs(";
  EXPECT_EQ(expression_error(calls).first_line, failure.first_line);
  std::string conditionals;
  for (int i = 0; i < 2000; ++i) conditionals += "1 ? ";
  EXPECT_EQ(expression_error(conditionals).first_line, failure.first_line);
  std::string macros = "#macro M(A) A #end ";
  for (int i = 0; i < 2000; ++i) macros += "M(";
  EXPECT_EQ(expression_error(macros).first_line, failure.first_line);
  std::string colors;
  for (int i = 0; i < 2000; ++i) colors += "rgb ";
  EXPECT_EQ(expression_error(colors).first_line, failure.first_line);
  // Prefix operators and #if blocks do not recurse: no limit below the input size.
  EXPECT_EQ(core_testing::eval_float(std::string(100000, '-') + "1"), 1.0);
  std::string ifs;
  for (int i = 0; i < 20000; ++i) ifs += "#if (1) ";
  ifs += "#declare R = 1; ";
  for (int i = 0; i < 20000; ++i) ifs += "#end ";
  EXPECT_EQ(core_testing::declared(ifs, "R"), 1.0);
}

TEST(Errors, StringsCannotGrowWithoutBound) {
  ParseOptions options;
  const Failure failure = scene_error(
      "#declare S = \"0123456789abcdef\";\n#while (1) #declare S = concat(S, S); #end", options);
  EXPECT_EQ(failure.first_line, "concat(): the string is too long");
  EXPECT_EQ(failure.loc.line, 2);
}

TEST(Errors, CopyingCountsAgainstTheTokenLimit) {
  ParseOptions options;
  options.max_tokens = 100000;
  // 64 KiB copied per iteration: the limit is reached after a few hundred iterations.
  const Failure strings = scene_error(
      "#declare S = \"0123456789abcdef\";\n#for (I, 1, 12) #declare S = concat(S, S); #end\n"
      "#while (1) #declare T = S; #end",
      options);
  EXPECT_EQ(strings.first_line,
            "the scene did more work than reading 100000 tokens (copying strings and arrays "
            "counts): runaway loop or recursion?");
  const Failure arrays = scene_error(
      "#declare A = array[100000];\n"
      "#while (1) #declare B = A; #declare B[0] = 1; #end",
      options);
  EXPECT_EQ(arrays.first_line, strings.first_line);
  EXPECT_EQ(arrays.loc.line, 2);
}

TEST(Errors, StatementsMustConsumeTokens) {
  const Failure failure = scene_error("#declare A = 1;\n5");
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 1);
}

}  // namespace
}  // namespace convray::sdl
