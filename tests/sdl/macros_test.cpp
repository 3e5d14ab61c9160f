// Macros (definition, calls wherever a token may be, scopes, recursion, optional
// parameters) and user functions.
#include <gtest/gtest.h>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::declared;
using core_testing::eval_float;
using core_testing::run;
using core_testing::scene_error;

TEST(Macros, ValueMacrosInExpressions) {
  EXPECT_EQ(declared("#macro Double(X) (X * 2) #end\n#declare A = Double(3);", "A"), 6.0);
  EXPECT_EQ(declared("#macro Double(X) X * 2 #end\n#declare A = Double(3) + 1;", "A"), 7.0);
  EXPECT_EQ(declared("#macro Two() 2 #end\n#declare A = Two() * Two();", "A"), 4.0);
  EXPECT_EQ(declared("#macro Add(A, B) A + B #end\n#declare R = Add(1, Add(2, 3));", "R"), 6.0);
  EXPECT_EQ(eval_float("#macro V() <1, 2, 3> #end V().y"), 2.0);
}

TEST(Macros, StatementMacros) {
  const ParseResult result =
      run("#macro SetBoth(V)\n  #declare A = V;\n  #declare B = V * 2;\n#end\n"
          "SetBoth(5)\n");
  EXPECT_EQ(core_testing::global_float(result, "A"), 5.0);
  EXPECT_EQ(core_testing::global_float(result, "B"), 10.0);
}

TEST(Macros, LocalsAreLocalToTheCall) {
  const ParseResult result =
      run("#declare X = 100;\n"
          "#macro M(P)\n  #local X = P + 1;\n  #declare Seen = X;\n#end\n"
          "M(1)\n");
  EXPECT_EQ(core_testing::global_float(result, "X"), 100.0);
  EXPECT_EQ(core_testing::global_float(result, "Seen"), 2.0);
  EXPECT_EQ(result.globals.count("P"), 0u);  // parameters are locals of the call
}

TEST(Macros, LocalAtTheEndOfABodyWithoutSemicolon) {
  // `#local R = 5` ends the body: its value dies with the call, the caller's R is untouched.
  EXPECT_EQ(declared("#declare R = 1; #macro M() #local R = 5 #end M() #declare S = R;", "S"), 1.0);
}

TEST(Macros, MacrosSeeTheirCallersLocals) {
  // POV-Ray's scopes are dynamic: the innermost table first, out to the global one.
  EXPECT_EQ(declared("#macro Inner() (Outer_Local * 10) #end\n"
                     "#macro Outer() #local Outer_Local = 4; #declare R = Inner(); #end\n"
                     "Outer()",
                     "R"),
            40.0);
}

TEST(Macros, IdentifiersArePassedByReferenceExpressionsByValue) {
  // POV-Ray 3.7's rule (tests/sdl/povray_macro_reference_test.cpp checks it against povray).
  EXPECT_EQ(declared("#declare A = 1; #macro M(P) #local P = 99; #end M(A)", "A"), 99.0);
  EXPECT_EQ(declared("#declare A = 1; #macro M(P) #local P = 99; #end M(A * 1)", "A"), 1.0);
}

TEST(Macros, Recursion) {
  EXPECT_EQ(declared("#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end\n"
                     "#declare F = Fact(10);",
                     "F"),
            3628800.0);
  // The value continues after the #else ... #end left in the macro body.
  EXPECT_EQ(declared("#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end\n"
                     "#declare F = Fact(3) + 1;",
                     "F"),
            7.0);
  EXPECT_EQ(declared("#macro Fib(N) #if (N < 2) N #else (Fib(N - 1) + Fib(N - 2)) #end #end\n"
                     "#declare F = Fib(15);",
                     "F"),
            610.0);
  EXPECT_EQ(
      declared("#declare Count = 0;\n"
               "#macro Down(N) #declare Count = Count + 1; #if (N > 0) Down(N - 1) #end #end\n"
               "Down(200)",
               "Count"),
      201.0);
}

TEST(Macros, RecursionIsLimited) {
  ParseOptions options;
  options.max_macro_depth = 50;
  const core_testing::Failure failure =
      scene_error("#macro Forever(N) Forever(N + 1) #end\nForever(0)", options);
  EXPECT_EQ(failure.first_line,
            "macro 'Forever' called more than 50 levels deep: runaway recursion?");
  EXPECT_EQ(failure.loc.line, 1);
  EXPECT_EQ(failure.loc.column, 19);
}

TEST(Macros, OptionalParameters) {
  EXPECT_EQ(declared("#macro M(A, optional B) #ifdef (B) #declare R = A + B; #else "
                     "#declare R = A; #end #end M(1)",
                     "R"),
            1.0);
  EXPECT_EQ(declared("#macro M(A, optional B) #ifdef (B) #declare R = A + B; #else "
                     "#declare R = A; #end #end M(1, 2)",
                     "R"),
            3.0);
  EXPECT_EQ(declared("#macro M(optional A, B) #ifdef (A) #declare R = A; #else "
                     "#declare R = -B; #end #end M(, 5)",
                     "R"),
            -5.0);
}

TEST(Macros, BreakLeavesAMacro) {
  EXPECT_EQ(
      declared("#macro M() #declare R = 1; #if (1) #break #end #declare R = 2; #end M()", "R"),
      1.0);
}

TEST(Macros, StringsAndVectorsAsArguments) {
  EXPECT_EQ(declared("#macro Len(S) strlen(S) #end #declare R = Len(concat(\"ab\", \"c\"));", "R"),
            3.0);
  EXPECT_EQ(
      declared("#macro Sum3(V) (V.x + V.y + V.z) #end #declare R = Sum3(<1, 2, 3> * 2);", "R"),
      12.0);
  EXPECT_EQ(declared("#declare A = array[2] {3, 4};\n"
                     "#macro Second(Arr) Arr[1] #end #declare R = Second(A);",
                     "R"),
            4.0);
}

TEST(Macros, MacroInsideAnObjectBody) {
  const ParseResult result =
      run("#macro Red() pigment { color rgb <1, 0, 0> } #end\n"
          "sphere { 0, 1 Red() }\n");
  ASSERT_EQ(result.scene.objects.size(), 1u);
  ASSERT_NE(result.scene.objects[0]->texture, nullptr);
  EXPECT_EQ(result.scene.objects[0]->texture->pigment.color.rgb, Vec3(1, 0, 0));
}

TEST(Macros, MacroMakingAnObject) {
  const ParseResult result =
      run("#macro Ball(R) sphere { 0, R } #end\n"
          "#declare B = Ball(2);\n"
          "object { B }\n"
          "Ball(3)\n");
  EXPECT_EQ(result.scene.objects.size(), 2u);
  EXPECT_NE(result.globals.at("B").get<scene::ObjectPtr>(), nullptr);
}

TEST(Macros, ArityErrors) {
  core_testing::Failure failure = scene_error("#macro M(A, B) A #end\n#declare R = M(1);");
  EXPECT_EQ(failure.first_line, "macro 'M' (defined at test.pov:1:1) takes 2 arguments, found 1");
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 14);
  failure = scene_error("#macro M(A) A #end\n#declare R = M(1, 2, 3);");
  EXPECT_EQ(failure.first_line, "macro 'M' (defined at test.pov:1:1) takes 1 argument, found 3");
  EXPECT_EQ(failure.loc.column, 19);
  failure = scene_error("#macro M(A, B) A #end\n#declare R = M(, 2);");
  EXPECT_EQ(failure.first_line, "missing argument 'A' of macro 'M'");
  failure = scene_error("#macro M(A) A #end\n#declare R = M;");
  EXPECT_EQ(failure.first_line, "expected '(' after the macro name 'M', found ';'");
  failure = scene_error("#macro M(A, A) #end");
  EXPECT_EQ(failure.first_line, "parameter 'A' appears twice in macro 'M'");
  failure = scene_error("#macro M(sphere) #end");
  EXPECT_EQ(failure.first_line,
            "'sphere' is a reserved word and cannot be used as an identifier as a parameter of "
            "macro 'M'");
}

TEST(Functions, UserFunctions) {
  EXPECT_EQ(eval_float("#declare F = function (a, b) { a * 10 + b } F(1, 2)"), 12.0);
  EXPECT_EQ(eval_float("#declare G = function { x + y * z } G(1, 2, 3)"), 7.0);
  EXPECT_EQ(eval_float("#declare Sq = function (x) { x * x } "
                       "#declare H = function (x) { Sq(x) + 1 } H(3)"),
            10.0);
  EXPECT_DOUBLE_EQ(eval_float("#declare sind = function (x) { sin(radians(x)) } sind(30)"),
                   std::sin(30.0 * std::acos(-1.0) / 180.0));
  // The body cannot run past its closing brace.
  EXPECT_EQ(core_testing::expression_error("#declare F = function { 1 2 } F(0, 0, 0)").first_line,
            "expected the end of the body of function 'F', found '2'");
  EXPECT_EQ(core_testing::expression_error("#declare F = function (a) { a } F(1, 2)").first_line,
            "function 'F' takes 1 argument, found 2");
  EXPECT_EQ(
      core_testing::expression_error("#declare F = function { internal(3) } F(1, 2, 3)").first_line,
      "internal function 3 ('F') is not supported yet by convray (at test.pov:1:25): 'F', "
      "declared at test.pov:1:14, needs it");
}

}  // namespace
}  // namespace convray::sdl
