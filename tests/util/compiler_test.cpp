// The build must round as the source says. GCC 12.2's SLP vectorizer once returned p
// unrounded from the function below (fixed by -fno-tree-slp-vectorize in CMakeLists.txt);
// meshes read as float32 (assimp) rely on this rounding being real.
#include <gtest/gtest.h>

namespace {

struct Pair {
  double x, y;
};

[[gnu::noinline]] Pair round_to_float(const Pair& p) {
  return Pair{static_cast<float>(p.x), static_cast<float>(p.y)};
}

TEST(Compiler, RoundsDoublesToFloatWhenTold) {
  const Pair q = round_to_float({0.1, 0.2});
  EXPECT_EQ(q.x, 0.100000001490116119384765625);  // float(0.1), exactly
  EXPECT_EQ(q.y, 0.20000000298023223876953125);   // float(0.2), exactly
}

TEST(Compiler, DoesNotFuseMultiplyAddsOutsideTheBatchEvaluators) {
  // With contraction, a*b - a*b can become fma(a, b, -(a*b)): the rounding error, not 0.
  volatile double a = 0.1, b = 0.7;
  const double x = a, y = b;
  EXPECT_EQ(x * y - x * y, 0.0);
}

}  // namespace
