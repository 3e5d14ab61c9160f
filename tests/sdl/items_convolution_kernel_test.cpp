// `kernel quartic` and `kernel cauchy [s]` in `convolution { }`: the kernel reaches the scene
// record, the offset gives the Cauchy plane's threshold, and bad input fails at file:line:col.
#include "field/threshold.hpp"
#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;
using field::KernelType;

scene::Implicit convolution_of(const ParseResult& result) {
  return shape_of<scene::Implicit>(only_object(result));
}

TEST(ItemsConvolutionKernel, QuarticIsTheDefault) {
  const auto& plain = convolution_of(parse("convolution { point { 0 } }"));
  EXPECT_EQ(plain.object.kernel.type, KernelType::quartic);
  const auto& given = convolution_of(parse("convolution { kernel quartic point { 0 } }"));
  EXPECT_EQ(given.object.kernel.type, KernelType::quartic);
  EXPECT_EQ(given.object.threshold, plain.object.threshold);
}

TEST(ItemsConvolutionKernel, CauchyWithAndWithoutSharpness) {
  const auto& one = convolution_of(parse("convolution { kernel cauchy point { 0 } }"));
  EXPECT_EQ(one.object.kernel.type, KernelType::cauchy);
  EXPECT_EQ(one.object.kernel.sharpness, 1.0);
  const auto& two = convolution_of(parse(R"(
    #declare S = 1.5;
    convolution { kernel cauchy 2*S radius 3 segment { 0, x } })"));
  EXPECT_EQ(two.object.kernel.type, KernelType::cauchy);
  EXPECT_EQ(two.object.kernel.sharpness, 3.0);
  EXPECT_EQ(two.object.segments[0].weight.radius, 3.0);  // the truncation margin
}

// The plane's field at distance D under the Cauchy kernel: strength pi / (s^2 (1 + s^2 D^2)).
TEST(ItemsConvolutionKernel, CauchyOffsetIsThePlanesField) {
  const auto& c = convolution_of(
      parse("convolution { kernel cauchy 2 strength 3 radius 2 offset 0.3 point { 0 } }"));
  EXPECT_NEAR(c.object.threshold, 3.0 * kPi / (4.0 * (1.0 + 4.0 * 0.09)), 1e-14);
  // Neither given: offset R/2 = 1, as for the quartic kernel.
  const auto& d = convolution_of(parse("convolution { kernel cauchy 0.5 radius 2 point { 0 } }"));
  EXPECT_NEAR(d.object.threshold, kPi / (0.25 * (1.0 + 0.25)), 1e-13);
  const auto& t = convolution_of(parse("convolution { kernel cauchy threshold 0.7 point { 0 } }"));
  EXPECT_EQ(t.object.threshold, 0.7);
}

TEST(ItemsConvolutionKernel, Errors) {
  EXPECT_TRUE(fails_with("convolution {\n  kernel cauchy 0 point { 0 } }", 2, 17,
                         "sharpness s must be positive"));
  EXPECT_TRUE(fails_with("convolution { kernel cauchy -1 point { 0 } }", 1, 29,
                         "sharpness s must be positive"));
  EXPECT_TRUE(fails_with("convolution { kernel gauss point { 0 } }", 1, 22,
                         "kernel must be quartic or cauchy"));
  EXPECT_TRUE(fails_with("convolution { kernel cauchy\n  arc { x, y, -x } }", 2, 3,
                         "kernel cauchy supports points, segments and triangles (meshes)"));
  EXPECT_TRUE(
      fails_with("convolution { kernel cauchy radius 1 offset 1 point { 0 } }", 1, 38, "offset"));
}

}  // namespace
}  // namespace convray::sdl
