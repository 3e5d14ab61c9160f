// Macro arguments passed by reference, as POV-Ray 3.7 passes them: an argument that is a bare
// identifier (or an array element) is the caller's variable itself, so #declare and #local of
// the parameter change it; any other expression is passed by value. Each scene is read by the
// installed povray and by our parser and what #debug prints must agree.
#include <gtest/gtest.h>

#include <string>

#include "core_test_support.hpp"
#include "povray_debug.hpp"

namespace convray::sdl {
namespace {

using core_testing::declared;
using core_testing::scene_error;
using povray_testing::convray_debug;
using povray_testing::povray_run;

void expect_as_povray(const std::string& scene) {
  const auto pov = povray_run("#version 3.7;\n" + scene);
  ASSERT_EQ(pov.exit_code, 0) << pov.messages;
  ASSERT_FALSE(pov.debug.empty()) << pov.messages;
  EXPECT_EQ(convray_debug("#version 3.7;\n" + scene), pov.debug) << scene;
}

const char* kSetters =
    "#macro SetD(P) #declare P = 5; #end\n"
    "#macro SetL(P) #local P = 6; #end\n"
    "#macro Show(Label, V) #debug concat(Label, \": \", str(V, 0, 0), \"\\n\") #end\n";

TEST(PovRayMacroReference, AnIdentifierArgumentIsTheCallersVariable) {
  // Without povray too: macro2.pov's pattern, a macro that assigns to its parameter.
  EXPECT_EQ(declared("#macro SetD(P) #declare P = 5; #end #declare A = 1; SetD(A)", "A"), 5.0);
  EXPECT_EQ(declared("#macro SetD(P) #declare P = 5; #end #declare A = 1; SetD(A + 0)", "A"),
            1.0);
  SKIP_WITHOUT_POVRAY();
  expect_as_povray(std::string(kSetters) +
                   "#declare A = 1; SetD(A) Show(\"declare\", A)\n"
                   "#declare A = 1; SetL(A) Show(\"local\", A)\n"
                   "#declare A = 1; SetD(A + 0) Show(\"expression\", A)\n"
                   "#declare A = 1; SetD((A)) Show(\"parenthesised\", A)\n"
                   "#declare A = 1; SetD(A.x) Show(\"component\", A)\n"
                   "#declare V = <1, 2, 3>; SetD(V) Show(\"vector\", V.x)\n"
                   "#declare S = \"x\"; #macro SetS(P) #declare P = \"changed\"; #end SetS(S)\n"
                   "#debug concat(\"string: \", S, \"\\n\")\n");
}

TEST(PovRayMacroReference, ArrayElementsChainsAndCallersLocals) {
  SKIP_WITHOUT_POVRAY();
  expect_as_povray(std::string(kSetters) +
                   "#declare Arr = array[3] {1, 2, 3}; #declare I = 1;\n"
                   "SetD(Arr[0]) SetL(Arr[I]) SetD(Arr[I + 1] + 0)\n"
                   "Show(\"a0\", Arr[0]) Show(\"a1\", Arr[1]) Show(\"a2\", Arr[2])\n"
                   "#macro Outer(Q) SetD(Q) #end\n"
                   "#declare A = 1; Outer(A) Show(\"chained\", A)\n"
                   "#macro Caller() #local L = 1; SetD(L) Show(\"caller's local\", L) #end\n"
                   "Caller()\n"
                   "#macro Two(P, R) #declare P = R; #end\n"
                   "#declare A = 1; Two(A, 7) Show(\"second argument\", A)\n");
}

TEST(PovRayMacroReference, TheParameterAndTheVariableAreOneValue) {
  SKIP_WITHOUT_POVRAY();
  expect_as_povray(
      std::string(kSetters) +
      "#macro SeeAssignment(P) #declare A = 9; Show(\"P sees\", P) #end\n"
      "#declare A = 1; SeeAssignment(A) Show(\"after\", A)\n"
      "#macro SeeParameter(P) #declare P = 3; Show(\"A sees\", A) #end\n"
      "#declare A = 1; SeeParameter(A)\n"
      "#macro UndefParameter(P) #undef P #end\n"
      "#declare A = 1; UndefParameter(A)\n"
      "#ifdef (A) Show(\"after #undef of the parameter\", A) #else #debug \"gone\\n\" #end\n"
      "#macro Grow(P) #declare P[1] = 20; #end\n"
      "#declare Arr = array[2] {1, 2}; Grow(Arr) Show(\"array through parameter\", Arr[1])\n"
      "#macro Count(N) #while (N < 4) #declare N = N + 1; #end #end\n"
      "#declare K = 0; Count(K) Show(\"loop\", K)\n");
}

TEST(PovRayMacroReference, AnUndeclaredIdentifierIsAnError) {
  // POV-Ray 3.7: "Cannot pass uninitialized identifier as macro parameter".
  EXPECT_NE(scene_error("#macro SetD(P) #declare P = 5; #end\nSetD(Nothing)").first_line.find(
                "Nothing"),
            std::string::npos);
}

TEST(PovRayMacroReference, NoCommaIsNeededAfterAnItemArgument) {
  // incdemo/shapes.pov: `Align_Object(Center_Object(...) -y, <0, 0, 0>)`.
  const std::string scene =
      "#macro M(O, V, W) #debug concat(vstr(3, V, \",\", 0, 1), \"|\", str(W, 0, 1), \"\\n\") "
      "#end\n"
      "M(sphere { 0, 1 } -y, 2)\n"
      "#declare T = texture { pigment { rgb 1 } }\n"
      "M(texture { T } <1, 2, 3>, 4)\n";
  EXPECT_NE(convray_debug(scene).find("-0.0,-1.0,-0.0|2.0"), std::string::npos);
  EXPECT_NE(scene_error("#macro M(A, B) #end M(1 2)").first_line.find("expected ')'"),
            std::string::npos);
  SKIP_WITHOUT_POVRAY();
  expect_as_povray(scene);
}

}  // namespace
}  // namespace convray::sdl
