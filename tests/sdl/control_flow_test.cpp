// #if #elseif #else #ifdef #ifndef #while #for #switch #case #range #break #end.
#include <gtest/gtest.h>

#include "core_test_support.hpp"

namespace convray::sdl {
namespace {

using core_testing::declared;
using core_testing::eval_float;
using core_testing::run;
using core_testing::scene_error;

TEST(ControlFlow, IfElse) {
  EXPECT_EQ(declared("#if (1) #declare R = 1; #else #declare R = 2; #end", "R"), 1.0);
  EXPECT_EQ(declared("#if (0) #declare R = 1; #else #declare R = 2; #end", "R"), 2.0);
  EXPECT_EQ(declared("#declare R = 0; #if (0) #declare R = 1; #end", "R"), 0.0);
  EXPECT_EQ(declared("#if (1e-11) #declare R = 1; #else #declare R = 2; #end", "R"), 2.0);
  EXPECT_EQ(declared("#if (2 > 1 & 3 > 2) #declare R = 1; #end", "R"), 1.0);
}

TEST(ControlFlow, ElseIfChains) {
  const auto pick = [](int n) {
    return declared("#declare N = " + std::to_string(n) +
                        ";\n#if (N = 1) #declare R = 10;\n#elseif (N = 2) #declare R = 20;\n"
                        "#elseif (N = 3) #declare R = 30;\n#else #declare R = 99;\n#end",
                    "R");
  };
  EXPECT_EQ(pick(1), 10.0);
  EXPECT_EQ(pick(2), 20.0);
  EXPECT_EQ(pick(3), 30.0);
  EXPECT_EQ(pick(4), 99.0);
}

TEST(ControlFlow, SkippedBranchesAreNotEvaluated) {
  // Nonsense, undeclared names and nested blocks in a branch not taken are never read.
  EXPECT_EQ(declared("#if (0)\n  #declare X = Undeclared / 0;\n  #while (1) #if (1) #end #end\n"
                     "  #macro M() #else #end\n#else\n  #declare R = 5;\n#end",
                     "R"),
            5.0);
}

TEST(ControlFlow, IfdefIfndef) {
  EXPECT_EQ(declared("#declare A = 1; #ifdef (A) #declare R = 1; #else #declare R = 2; #end", "R"),
            1.0);
  EXPECT_EQ(declared("#ifdef (A) #declare R = 1; #else #declare R = 2; #end", "R"), 2.0);
  EXPECT_EQ(declared("#ifndef (A) #declare R = 1; #else #declare R = 2; #end", "R"), 1.0);
  // A macro name is declared too, and is not called by #ifdef.
  EXPECT_EQ(declared("#macro M() #error \"called\" #end #ifdef (M) #declare R = 3; #end", "R"),
            3.0);
  // The include-guard idiom.
  EXPECT_EQ(declared("#ifndef (Guard) #declare Guard = 1; #declare R = 1; #end\n"
                     "#ifndef (Guard) #declare R = 2; #end",
                     "R"),
            1.0);
}

TEST(ControlFlow, NestedIfs) {
  EXPECT_EQ(declared("#declare A = 1; #declare B = 0;\n"
                     "#if (A) #if (B) #declare R = 1; #else #declare R = 2; #end\n"
                     "#else #if (B) #declare R = 3; #else #declare R = 4; #end #end",
                     "R"),
            2.0);
}

TEST(ControlFlow, While) {
  EXPECT_EQ(declared("#declare I = 0; #declare Sum = 0;\n"
                     "#while (I < 10) #declare Sum = Sum + I; #declare I = I + 1; #end",
                     "Sum"),
            45.0);
  EXPECT_EQ(declared("#declare R = 7; #while (0) #declare R = 0; #end", "R"), 7.0);
}

TEST(ControlFlow, NestedLoops) {
  EXPECT_EQ(declared("#declare Count = 0; #declare I = 0;\n"
                     "#while (I < 4) #declare J = 0;\n"
                     "  #while (J < I) #declare Count = Count + 1; #declare J = J + 1; #end\n"
                     "  #declare I = I + 1;\n#end",
                     "Count"),
            6.0);  // 0 + 1 + 2 + 3
}

TEST(ControlFlow, For) {
  EXPECT_EQ(declared("#declare Sum = 0; #for (I, 1, 10) #declare Sum = Sum + I; #end", "Sum"),
            55.0);
  EXPECT_EQ(declared("#declare Sum = 0; #for (I, 10, 1, -3) #declare Sum = Sum + I; #end", "Sum"),
            10.0 + 7 + 4 + 1);
  EXPECT_EQ(declared("#declare N = 0; #for (T, 0, 1, 0.1) #declare N = N + 1; #end", "N"), 11.0);
  EXPECT_EQ(declared("#declare N = 0; #for (I, 5, 1) #declare N = N + 1; #end", "N"), 0.0);
  // As POV-Ray's `#local I = Start; #while (I <= End) ... #local I = I + Step; #end`.
  EXPECT_EQ(declared("#for (I, 1, 3) #end #declare After = I;", "After"), 4.0);
}

TEST(ControlFlow, Switch) {
  const auto pick = [](double value) {
    return declared("#declare R = -1;\n#switch (" + std::to_string(value) +
                        ")\n"
                        "  #case (1) #declare R = 10; #break\n"
                        "  #case (2) #declare R = 20; #break\n"
                        "  #range (3, 5) #declare R = 30; #break\n"
                        "  #else #declare R = 99;\n"
                        "#end",
                    "R");
  };
  EXPECT_EQ(pick(1), 10.0);
  EXPECT_EQ(pick(2), 20.0);
  EXPECT_EQ(pick(3), 30.0);
  EXPECT_EQ(pick(4.5), 30.0);
  EXPECT_EQ(pick(5), 30.0);
  EXPECT_EQ(pick(6), 99.0);
  EXPECT_EQ(pick(0), 99.0);
}

TEST(ControlFlow, SwitchFallsThroughWithoutBreak) {
  EXPECT_EQ(declared("#declare R = 0;\n#switch (1)\n"
                     "  #case (1) #declare R = R + 1;\n"
                     "  #case (2) #declare R = R + 10;\n"
                     "  #break\n"
                     "  #case (3) #declare R = R + 100;\n"
                     "#end",
                     "R"),
            11.0);
  // Without a match and without #else nothing runs.
  EXPECT_EQ(declared("#declare R = 0; #switch (7) #case (1) #declare R = 1; #end", "R"), 0.0);
  // An #else after a clause that ran ends it.
  EXPECT_EQ(declared("#declare R = 0; #switch (1) #case (1) #declare R = 1; #else "
                     "#declare R = 2; #end",
                     "R"),
            1.0);
}

TEST(ControlFlow, BreakLeavesLoops) {
  EXPECT_EQ(declared("#declare I = 0;\n#while (1)\n  #declare I = I + 1;\n"
                     "  #if (I = 5) #break #end\n#end",
                     "I"),
            5.0);
  EXPECT_EQ(declared("#declare Sum = 0;\n#for (I, 1, 100)\n"
                     "  #if (I > 3) #if (1) #break #end #end\n"
                     "  #declare Sum = Sum + I;\n#end",
                     "Sum"),
            6.0);
}

TEST(ControlFlow, BreakInASwitchInsideALoopLeavesTheSwitch) {
  EXPECT_EQ(declared("#declare Sum = 0;\n#for (I, 1, 4)\n"
                     "  #switch (I) #case (2) #declare Sum = Sum + 20; #break\n"
                     "    #else #declare Sum = Sum + 1; #end\n#end",
                     "Sum"),
            23.0);
}

TEST(ControlFlow, ConditionsMayCallMacros) {
  EXPECT_EQ(declared("#macro Big(N) (N > 10) #end #if (Big(20)) #declare R = 1; #end", "R"), 1.0);
}

TEST(ControlFlow, LoopsCanSpanMacroCallsAndIncludes) {
  EXPECT_EQ(declared("#macro Add(N) #declare Sum = Sum + N; #end\n#declare Sum = 0;\n"
                     "#for (I, 1, 4) Add(I) #end",
                     "Sum"),
            10.0);
}

TEST(ControlFlow, LoopIterationsAreLimited) {
  ParseOptions options;
  options.max_loop_iterations = 1000;
  core_testing::Failure failure = scene_error("\n  #while (1) #end", options);
  EXPECT_EQ(failure.first_line, "#while loop exceeded 1000 iterations");
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 3);
  failure = scene_error("#for (I, 0, 1e9) #end", options);
  EXPECT_EQ(failure.first_line, "#for loop exceeded 1000 iterations");
  // 1000 iterations are allowed.
  EXPECT_EQ(declared("#declare N = 0; #while (N < 1000) #declare N = N + 1; #end", "N", options),
            1000.0);
}

// A loop's iterations count for the loops it runs inside: nested loops of 40 x 40 iterations
// are 1600 for the outer one (reported at the outer loop), whether the inner loop is written in
// place or runs in a macro; 30 x 30 stay within the limit.
TEST(ControlFlow, NestedLoopIterationsCountForTheEnclosingLoop) {
  ParseOptions options;
  options.max_loop_iterations = 1000;
  const std::string nested =
      "#declare I = 0;\n#while (I < N)\n  #declare J = 0;\n"
      "  #while (J < N) #declare J = J + 1; #end\n  #declare I = I + 1;\n#end\n";
  const core_testing::Failure failure = scene_error("#declare N = 40;\n" + nested, options);
  EXPECT_EQ(failure.first_line,
            "#while loop exceeded 1000 iterations (counting those of the loops inside it)");
  EXPECT_EQ(failure.loc.line, 3);
  EXPECT_EQ(failure.loc.column, 1);
  EXPECT_EQ(declared("#declare N = 30;\n" + nested + "#declare Done = I * J;", "Done", options),
            900.0);
  const core_testing::Failure in_macro = scene_error(
      "#macro Inner() #for (J, 1, 40) #end #end\n#for (I, 1, 40) Inner() #end", options);
  EXPECT_EQ(in_macro.first_line,
            "#for loop exceeded 1000 iterations (counting those of the loops inside it)");
  EXPECT_EQ(in_macro.loc.line, 2);
}

TEST(ControlFlow, DefaultLoopLimitMessage) {
  ParseOptions options;
  options.max_loop_iterations = 10'000'000;
  EXPECT_EQ(scene_error("#declare I = 0; #while (1) #declare I = I + 1; #if (I > 5) #error "
                        "\"stop\" #end #end",
                        options)
                .first_line,
            "stop");
}

TEST(ControlFlow, TokensReadAreLimited) {
  ParseOptions options;
  options.max_tokens = 5000;
  const core_testing::Failure failure =
      scene_error("#declare I = 0; #while (I < 1e6) #declare I = I + 1; #end", options);
  EXPECT_EQ(failure.first_line, "the scene read more than 5000 tokens: runaway loop or recursion?");
}

TEST(ControlFlow, SkippingAMillionLinesIsFast) {
  std::string text = "#declare R = 1;\n#if (0)\n";
  for (int i = 0; i < 200000; ++i) text += "  #declare A = <1, 2, 3> * 4; sphere { 0, 1 }\n";
  text += "#else #declare R = 2; #end\n";
  EXPECT_EQ(declared(text, "R"), 2.0);
}

TEST(ControlFlow, Errors) {
  core_testing::Failure failure = scene_error("#declare A = 1;\n#else\n");
  EXPECT_EQ(failure.first_line, "#else without #if");
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 1);
  EXPECT_EQ(scene_error("#elseif (1)").first_line, "#elseif without #if");
  EXPECT_EQ(scene_error("#while (0) #end #end").first_line,
            "#end without #if, #while, #for, #switch or #macro");
  EXPECT_EQ(scene_error("#break").first_line, "#break outside #switch, #while, #for or a macro");
  EXPECT_EQ(scene_error("#case (1)").first_line, "#case without #switch");
  EXPECT_EQ(scene_error("#for (I, 1, 2, 0) #end").first_line,
            "#for loop with a step of zero never ends");
  failure = scene_error("#if 1 #end");
  EXPECT_EQ(failure.first_line, "expected '(' after the directive, found '1'");
  EXPECT_EQ(failure.loc.column, 5);
  failure = scene_error("#if (<1, 2>) #end");
  EXPECT_EQ(failure.first_line, "expected a float as the condition, found a vector");
}

TEST(ControlFlow, UnterminatedBlocksNameTheirOpening) {
  core_testing::Failure failure = scene_error("#declare A = 1;\n#if (A)\n#declare B = 2;\n");
  EXPECT_EQ(failure.first_line,
            "unterminated #if (opened at 2:1): expected #end before the end of the file");
  EXPECT_EQ(failure.loc.line, 4);  // the end of the file
  EXPECT_EQ(failure.loc.column, 1);
  failure = scene_error("#if (0)\n  #if (1)\n#end\n");  // skipped: the inner #if counts
  EXPECT_EQ(failure.first_line,
            "unterminated #if (opened at 1:1): expected #end before the end of the file");
  failure = scene_error("#declare I = 0;\n  #while (I < 2) #declare I = I + 1;");
  EXPECT_EQ(failure.first_line,
            "unterminated #while (opened at 2:3): expected #end before the end of the file");
  failure = scene_error("#macro M()\n  #declare A = 1;\n");
  EXPECT_EQ(failure.first_line,
            "unterminated #macro (opened at 1:1): expected #end before the end of the file");
  failure = scene_error("#switch (3) #case (1) #break");
  EXPECT_EQ(failure.first_line,
            "unterminated #switch (opened at 1:1): expected #end before the end of the file");
}

}  // namespace
}  // namespace convray::sdl
