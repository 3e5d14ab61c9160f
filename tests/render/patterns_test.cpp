// Pattern values at chosen points: the exact patterns (checker, gradient, radial, onion,
// marble, wood, leopard) against POV-Ray 3.7's values (read from its 16-bit renders, see
// patterns.hpp; they agree with the formulas to a few 1e-5) and formulas; colour maps; and our
// noise's promises.
#include "render/patterns.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "render/noise.hpp"
#include "render/pigment.hpp"

namespace convray::render {
namespace {

using scene::Pattern;

scene::PatternSpace space_of(Pattern pattern) {
  scene::PatternSpace space;
  space.pattern = pattern;
  return space;
}

TEST(Patterns, CheckerAlternatesUnitCubes) {
  const scene::PatternSpace checker = space_of(Pattern::checker);
  EXPECT_EQ(pattern_value(checker, Vec3(0.5, 0.5, 0.5)), 0.0);
  EXPECT_EQ(pattern_value(checker, Vec3(1.5, 0.5, 0.5)), 1.0);
  EXPECT_EQ(pattern_value(checker, Vec3(1.5, 1.5, 0.5)), 0.0);
  EXPECT_EQ(pattern_value(checker, Vec3(-0.5, 0.5, 0.5)), 1.0);
  // POV-Ray 3.7 at (-1.95, 0, 1.45): floor sum -2 + 0 + 1 = -1, odd: the second colour.
  EXPECT_EQ(pattern_value(checker, Vec3(-1.95, 0.0, 1.45)), 1.0);
}

TEST(Patterns, CheckerOnAPlaneAtZeroIgnoresRoundingBelowIt) {
  // A hit point of the plane y = 0 may come out at y = -1e-17: it keeps the colour of y = 0,
  // as in POV-Ray (which flips only from about y = -1e-9 on).
  const scene::PatternSpace checker = space_of(Pattern::checker);
  EXPECT_EQ(pattern_value(checker, Vec3(0.5, -1e-17, 0.5)),
            pattern_value(checker, Vec3(0.5, 0.0, 0.5)));
  EXPECT_NE(pattern_value(checker, Vec3(0.5, -1e-6, 0.5)),
            pattern_value(checker, Vec3(0.5, 0.0, 0.5)));
}

TEST(Patterns, GradientIsTheFractionalPartAlongTheNormalisedAxis) {
  scene::PatternSpace gradient = space_of(Pattern::gradient);
  EXPECT_NEAR(pattern_value(gradient, Vec3(-1.95, 1.45, 0)), 0.05, 1e-12);
  EXPECT_NEAR(pattern_value(gradient, Vec3(1.95, -1.45, 0)), 0.95, 1e-12);
  gradient.gradient_axis = Vec3(-1, 0, 0);
  EXPECT_NEAR(pattern_value(gradient, Vec3(-1.95, 0, 0)), 0.95, 1e-12);
  // POV-Ray: gradient <1,1,0> at (-1.95, 1.45): fract(-0.5 / sqrt 2) = 0.64645.
  gradient.gradient_axis = Vec3(1, 1, 0);
  EXPECT_NEAR(pattern_value(gradient, Vec3(-1.95, 1.45, 0)), 0.646447, 1e-6);
}

TEST(Patterns, FrequencyAndPhaseWrapTheValue) {
  scene::PatternSpace gradient = space_of(Pattern::gradient);
  gradient.frequency = 2.0;
  gradient.phase = 0.3;
  // POV-Ray 3.7: 0.4 at x = 0.05 and 0.2 at x = 1.95.
  EXPECT_NEAR(pattern_value(gradient, Vec3(0.05, 0, 0)), 0.4, 1e-12);
  EXPECT_NEAR(pattern_value(gradient, Vec3(1.95, 0, 0)), 0.2, 1e-12);
}

TEST(Patterns, PatternsAreEvaluatedInTheirOwnSpace) {
  scene::PatternSpace gradient = space_of(Pattern::gradient);
  gradient.transform = scene::Transform::scaling(Vec3(0.7));
  // POV-Ray 3.7: gradient x scale 0.7 at x = -1.95 gives 0.21431.
  EXPECT_NEAR(pattern_value(gradient, Vec3(-1.95, 1.45, 0)), 0.214286, 1e-6);
}

TEST(Patterns, RadialTurnsFromPlusXTowardsMinusZ) {
  const scene::PatternSpace radial = space_of(Pattern::radial);
  EXPECT_NEAR(pattern_value(radial, Vec3(1, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(pattern_value(radial, Vec3(0, 0, -1)), 0.25, 1e-12);
  EXPECT_NEAR(pattern_value(radial, Vec3(-1, 0, 1e-300)), 0.5, 1e-12);
  EXPECT_NEAR(pattern_value(radial, Vec3(0, 5, 1)), 0.75, 1e-12);
  // POV-Ray 3.7 values: (1.55, 1.15) -> 0.89841, (-1.95, 1.45) -> 0.60175.
  EXPECT_NEAR(pattern_value(radial, Vec3(1.55, 0, 1.15)), 0.89841, 5e-5);
  EXPECT_NEAR(pattern_value(radial, Vec3(-1.95, 0, 1.45)), 0.60175, 5e-5);
}

TEST(Patterns, OnionIsTheFractionalDistanceFromTheOrigin) {
  const scene::PatternSpace onion = space_of(Pattern::onion);
  EXPECT_NEAR(pattern_value(onion, Vec3(0, 3, 4) * 0.5), 0.5, 1e-12);
  EXPECT_NEAR(pattern_value(onion, Vec3(-1.95, 1.45, 0)), 0.43001, 5e-5);  // POV-Ray 3.7
}

TEST(Patterns, MarbleAndWoodAreTriangleWaves) {
  const scene::PatternSpace marble = space_of(Pattern::marble);
  EXPECT_NEAR(pattern_value(marble, Vec3(0.05, 0, 0)), 0.1, 1e-12);
  // 0.9 but for POV-Ray's wrap, which drifts by 1e-5 per unit of x (its values: 0.89998 and
  // 0.90002).
  EXPECT_NEAR(pattern_value(marble, Vec3(-1.45, 0, 0)), 0.89998, 1e-12);
  EXPECT_NEAR(pattern_value(marble, Vec3(1.55, 7, 3)), 0.90002, 1e-12);
  const scene::PatternSpace wood = space_of(Pattern::wood);
  EXPECT_NEAR(pattern_value(wood, Vec3(-1.95, 1.45, 0)), 0.86000, 5e-5);  // POV-Ray 3.7
  EXPECT_NEAR(pattern_value(wood, Vec3(0.05, -0.05, 9)), 0.14142, 5e-5);
}

TEST(Patterns, LeopardIsTheSquaredMeanOfSines) {
  const Vec3 p(-0.95, -0.55, 0.0);
  const double s = (std::sin(p.x) + std::sin(p.y)) / 3.0;
  EXPECT_NEAR(pattern_value(space_of(Pattern::leopard), p), s * s, 1e-12);
  EXPECT_NEAR(s * s, 0.198, 5e-4);  // POV-Ray 3.7's value there
}

TEST(Patterns, PlanarSphericalCylindricalAndBoxedFallFromOneToZero) {
  // Values read from POV-Ray 3.7's 16-bit renders of each pattern on a plane.
  EXPECT_NEAR(pattern_value(space_of(Pattern::planar), Vec3(-0.625, -0.625, 0)), 0.37501, 5e-5);
  EXPECT_NEAR(pattern_value(space_of(Pattern::planar), Vec3(3, 0.125, -9)), 0.87500, 5e-5);
  EXPECT_EQ(pattern_value(space_of(Pattern::planar), Vec3(0, 1.5, 0)), 0.0);
  EXPECT_NEAR(pattern_value(space_of(Pattern::spherical), Vec3(-0.125, 0.875, 0)), 0.11612, 5e-5);
  EXPECT_NEAR(pattern_value(space_of(Pattern::cylindrical), Vec3(0.125, 7, 0.125)), 0.82322,
              5e-5);
  EXPECT_NEAR(pattern_value(space_of(Pattern::boxed), Vec3(0.125, 0.125, 0.3)), 0.70001, 5e-5);
  EXPECT_NEAR(pattern_value(space_of(Pattern::boxed), Vec3(-0.625, -0.625, 0.3)), 0.37501, 5e-5);
  // The centre's 1 is kept, not wrapped to 0.
  EXPECT_EQ(pattern_value(space_of(Pattern::spherical), Vec3(0)), 1.0);
}

TEST(Patterns, Spiral1WindsItsArmsAboutZ) {
  // POV-Ray 3.7's values: spiral1 3 ramp_wave and spiral1 2 (its default triangle wave).
  scene::PatternSpace spiral = space_of(Pattern::spiral1);
  spiral.arms = 3.0;
  spiral.wave = scene::Wave::ramp;
  EXPECT_NEAR(pattern_value(spiral, Vec3(-0.125, 0.875, 0.3)), 0.75161, 5e-5);
  EXPECT_NEAR(pattern_value(spiral, Vec3(0.125, 0.125, 0.3)), 0.60177, 5e-5);
  spiral.arms = 2.0;
  spiral.wave = scene::Wave::pattern_default;
  EXPECT_NEAR(pattern_value(spiral, Vec3(-0.625, -0.625, -0.2)), 0.86772, 5e-5);
  EXPECT_NEAR(pattern_value(spiral, Vec3(-0.125, 0.875, -0.2)), 0.54192, 5e-5);
}

TEST(Patterns, MandelIsTheEscapeTimeOverTheIterations) {
  // POV-Ray 3.7's values for mandel 50 (its 16-bit renders).
  scene::PatternSpace mandel = space_of(Pattern::mandel);
  mandel.iterations = 50;
  EXPECT_NEAR(pattern_value(mandel, Vec3(-0.9875, 0.7375, 0)), 0.04, 1e-5);
  EXPECT_NEAR(pattern_value(mandel, Vec3(0.35, 0.05, 3)), 0.16, 1e-5);
  EXPECT_NEAR(pattern_value(mandel, Vec3(-1.325, 1.475, 0)), 0.0, 1e-5);
  EXPECT_EQ(pattern_value(mandel, Vec3(-0.1, 0.2, 0)), 1.0);  // inside: 1, not wrapped to 0
}

TEST(Patterns, DentsAreCubedBumps) {
  const Vec3 p(0.3, 1.7, -2.2);
  const double bumps = pattern_value(space_of(Pattern::bumps), p);
  EXPECT_NEAR(pattern_value(space_of(Pattern::dents), p), bumps * bumps * bumps, 1e-12);
}

TEST(Patterns, NoiseBasedPatternsStayInTheUnitInterval) {
  for (Pattern pattern : {Pattern::bozo, Pattern::granite, Pattern::agate, Pattern::leopard,
                          Pattern::ripples, Pattern::waves, Pattern::wrinkles, Pattern::spotted}) {
    for (int k = 0; k < 200; ++k) {
      const Vec3 p(0.37 * k - 20.0, std::sin(k) * 9.0, 0.11 * k * k - 7.0);
      const double v = pattern_value(space_of(pattern), p);
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 1.0);
    }
  }
}

scene::Color grey(double v) { return scene::Color{Vec3(v), 0.0, 0.0}; }

TEST(ColorMap, InterpolatesBetweenEntriesAndClampsOutside) {
  const std::vector<scene::ColorMapEntry> map = {
      {0.2, grey(0.0)}, {0.6, scene::Color{Vec3(1.0, 0.5, 0.0), 0.4, 0.2}}, {0.8, grey(1.0)}};
  EXPECT_EQ(lookup_color_map(map, 0.0).rgb, Vec3(0.0));   // before the first: the first
  EXPECT_EQ(lookup_color_map(map, 0.95).rgb, Vec3(1.0));  // after the last: the last
  const scene::Color mid = lookup_color_map(map, 0.5);    // 3/4 of the way from 0.2 to 0.6
  EXPECT_NEAR(mid.rgb.r, 0.75, 1e-12);
  EXPECT_NEAR(mid.rgb.g, 0.375, 1e-12);
  EXPECT_NEAR(mid.filter, 0.3, 1e-12);
  EXPECT_NEAR(mid.transmit, 0.15, 1e-12);
  EXPECT_NEAR(lookup_color_map(map, 0.7).rgb.b, 0.5, 1e-12);
}

TEST(ColorMap, EqualValuesMakeASharpEdge) {
  const std::vector<scene::ColorMapEntry> map = {
      {0.0, grey(0.1)}, {0.5, grey(0.2)}, {0.5, grey(0.9)}, {1.0, grey(1.0)}};
  EXPECT_NEAR(lookup_color_map(map, 0.4999).rgb.r, 0.2, 1e-3);
  EXPECT_NEAR(lookup_color_map(map, 0.5001).rgb.r, 0.9, 1e-3);
}

TEST(ColorMap, DefaultMapsAsPovRayHasThem) {
  // Measured on POV-Ray 3.7: marble at 0.3 is <0.9, 0.56, 0.56>; bozo between 0.4 and 0.6 is
  // green; the grey ramp elsewhere.
  const scene::Color marble = lookup_color_map(default_color_map(Pattern::marble), 0.3);
  EXPECT_NEAR(marble.rgb.r, 0.9, 1e-12);
  EXPECT_NEAR(marble.rgb.g, 0.56, 1e-12);
  EXPECT_EQ(lookup_color_map(default_color_map(Pattern::bozo), 0.5).rgb, Vec3(0, 1, 0));
  EXPECT_NEAR(lookup_color_map(default_color_map(Pattern::gradient), 0.3).rgb.g, 0.3, 1e-12);
}

TEST(Pigment, CheckerUsesItsBlockColoursOrPovRaysDefaults) {
  scene::Pigment pigment;
  pigment.space.pattern = Pattern::checker;
  EXPECT_EQ(evaluate_pigment(pigment, Vec3(0.5)).rgb, Vec3(0, 0, 1));  // default: blue, green
  EXPECT_EQ(evaluate_pigment(pigment, Vec3(1.5, 0.5, 0.5)).rgb, Vec3(0, 1, 0));
  pigment.block_colors = {grey(1.0)};
  EXPECT_EQ(evaluate_pigment(pigment, Vec3(0.5)).rgb, Vec3(1.0));
  EXPECT_EQ(evaluate_pigment(pigment, Vec3(1.5, 0.5, 0.5)).rgb, Vec3(0, 1, 0));
  pigment.block_colors = {grey(1.0), grey(0.25)};
  EXPECT_EQ(evaluate_pigment(pigment, Vec3(1.5, 0.5, 0.5)).rgb, Vec3(0.25));
}

TEST(Pigment, PatternThroughTheSceneMap) {
  scene::Pigment pigment;
  pigment.space.pattern = Pattern::gradient;
  pigment.color_map = {{0.0, grey(0.0)}, {1.0, grey(0.5)}};
  EXPECT_NEAR(evaluate_pigment(pigment, Vec3(0.5, 3, 3)).rgb.r, 0.25, 1e-12);
  pigment.space.pattern = Pattern::solid;
  pigment.color = scene::Color{Vec3(0.1, 0.2, 0.3), 0.5, 0.25};
  const scene::Color solid = evaluate_pigment(pigment, Vec3(9));
  EXPECT_EQ(solid.rgb, Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(solid.filter, 0.5);
  EXPECT_EQ(solid.transmit, 0.25);
}

}  // namespace
}  // namespace convray::render
