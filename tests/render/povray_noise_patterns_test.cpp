// The noise-based patterns against POV-Ray 3.7's: the installed povray prints
// `function { pattern { ... } }` at random points and our pattern values must agree.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "reference/povray_debug_stream.hpp"
#include "render/patterns.hpp"

namespace convray::render {
namespace {

using povray_testing::povray_run;
using scene::Pattern;

// Random points whose coordinates have 9 decimals, exactly as POV-Ray reads them.
std::vector<Vec3> random_points(unsigned seed, int count, double lo, double hi) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(lo, hi);
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    Vec3 p;
    for (int axis = 0; axis < 3; ++axis) {
      std::ostringstream text;
      text.precision(9);
      text << std::fixed << coordinate(random);
      p[axis] = std::stod(text.str());
    }
    points.push_back(p);
  }
  return points;
}

// POV-Ray's value of `pattern { <pattern_text> }` at each point.
std::vector<double> povray_pattern(const std::string& pattern_text,
                                   const std::vector<Vec3>& points) {
  std::ostringstream scene;
  scene.precision(9);
  scene << std::fixed << "#version 3.7;\n#declare F = function { pattern { " << pattern_text
        << " } }\n";
  for (const Vec3& p : points) {
    scene << "#debug concat(str(F(" << p.x << "," << p.y << "," << p.z << "),0,18),\"\\n\")\n";
  }
  std::istringstream printed(povray_run(scene.str()).debug);
  std::vector<double> values;
  for (double v; printed >> v;) values.push_back(v);
  return values;
}

void expect_matches_povray(const std::string& pattern_text, const scene::PatternSpace& space,
                           const std::vector<Vec3>& points, double tolerance) {
  const std::vector<double> pov = povray_pattern(pattern_text, points);
  ASSERT_EQ(pov.size(), points.size()) << pattern_text;
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_NEAR(pattern_value_in_space(space, points[k]), pov[k], tolerance)
        << pattern_text << " at " << points[k].x << " " << points[k].y << " " << points[k].z;
  }
}

scene::PatternSpace space_of(Pattern pattern) {
  scene::PatternSpace space;
  space.pattern = pattern;
  return space;
}

TEST(PovRayNoisePatterns, NoiseValuedPatternsMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::vector<Vec3> points = random_points(31, 150, -40.0, 40.0);
  const std::pair<const char*, Pattern> patterns[] = {
      {"bozo", Pattern::bozo},         {"spotted", Pattern::spotted},
      {"bumps", Pattern::bumps},       {"dents", Pattern::dents},
      {"granite", Pattern::granite},   {"wrinkles", Pattern::wrinkles},
      {"agate", Pattern::agate}};
  for (const auto& [text, pattern] : patterns) {
    expect_matches_povray(text, space_of(pattern), points, 1e-12);
  }
}

TEST(PovRayNoisePatterns, GeneratorOneAndAgateTurbMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::vector<Vec3> points = random_points(32, 100, -30.0, 30.0);
  scene::PatternSpace bozo = space_of(Pattern::bozo);
  bozo.noise_generator = 1;
  expect_matches_povray("bozo noise_generator 1", bozo, points, 1e-12);
  scene::PatternSpace agate = space_of(Pattern::agate);
  agate.agate_turb = 0.37;
  expect_matches_povray("agate agate_turb 0.37", agate, points, 1e-12);
}

// Marble takes its turbulence as a scalar sum along x (not the warp): checked where
// x + turbulence stays within [0, 1), as POV-Ray's ramp drifts by 1e-5 per unit of x.
TEST(PovRayNoisePatterns, MarbleTurbulenceMatches) {
  SKIP_WITHOUT_POVRAY();
  std::vector<Vec3> points = random_points(33, 150, 0.0, 40.0);
  for (Vec3& p : points) p.x = std::round((0.05 + 0.2 * (p.x / 40.0)) * 1e6) / 1e6;
  scene::PatternSpace marble = space_of(Pattern::marble);
  marble.wave = scene::Wave::ramp;
  marble.turbulence.amount = Vec3(0.3, 0.7, 0.9);  // only x counts
  marble.turbulence.octaves = 4;
  marble.turbulence.omega = 0.6;
  marble.turbulence.lambda = 2.2;
  expect_matches_povray("marble ramp_wave turbulence <0.3, 0.7, 0.9> octaves 4 omega 0.6 "
                        "lambda 2.2",
                        marble, points, 1e-12);
}

// Wood's turbulence moves x and y by sines of the warp (render/noise_patterns.hpp); marble and
// wood wrap with POV-Ray's drift of 1e-5 per unit, checked here out to |x| = 40.
TEST(PovRayNoisePatterns, WoodTurbulenceAndTheDriftingWrapMatch) {
  SKIP_WITHOUT_POVRAY();
  const std::vector<Vec3> points = random_points(36, 150, -40.0, 40.0);
  scene::PatternSpace wood = space_of(Pattern::wood);
  wood.wave = scene::Wave::ramp;
  wood.turbulence.amount = Vec3(0.05, 0.08, 0.3);
  wood.turbulence.octaves = 3;
  wood.turbulence.omega = 0.7;
  wood.turbulence.lambda = 2.3;
  expect_matches_povray("wood ramp_wave turbulence <0.05, 0.08, 0.3> octaves 3 omega 0.7 "
                        "lambda 2.3",
                        wood, points, 1e-11);
  expect_matches_povray("marble", space_of(Pattern::marble), points, 1e-11);
  expect_matches_povray("wood", space_of(Pattern::wood), points, 1e-11);
}

// Bozo with turbulence: the warp of render/noise.hpp, then the noise.
TEST(PovRayNoisePatterns, WarpedBozoMatches) {
  SKIP_WITHOUT_POVRAY();
  const std::vector<Vec3> points = random_points(34, 100, -20.0, 20.0);
  scene::PatternSpace bozo = space_of(Pattern::bozo);
  bozo.turbulence.amount = Vec3(0.5, 0.2, 0.8);
  expect_matches_povray("bozo turbulence <0.5, 0.2, 0.8>", bozo, points, 1e-12);
}

// Properties that need no POV-Ray: granite and wrinkles are sums of clamped octaves, so they
// stay within their bounds (granite <= sum of 1/2^(k+1), wrinkles <= sum of 1/2^(k+1)).
TEST(PovRayNoisePatterns, FractalSumsStayWithinTheirBounds) {
  for (const Vec3& p : random_points(35, 3000, -100.0, 100.0)) {
    const double g = raw_pattern_value(space_of(Pattern::granite), p);
    const double w = raw_pattern_value(space_of(Pattern::wrinkles), p);
    EXPECT_GE(g, 0.0);
    EXPECT_LE(g, 63.0 / 64.0);
    EXPECT_GE(w, 0.0);
    EXPECT_LE(w, 1023.0 / 1024.0);
  }
}

}  // namespace
}  // namespace convray::render
