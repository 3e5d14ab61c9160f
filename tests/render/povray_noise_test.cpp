// Our noise against POV-Ray 3.7's: the installed povray prints its noise (functions.inc's
// f_noise3d) and its turbulence warp at random points, and ours must give the same numbers.
// Then properties that hold whatever the tables: continuity of value and slope across cell
// faces, the 4096-cell period, the range.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "reference/povray_debug_stream.hpp"
#include "render/noise.hpp"

namespace convray::render {
namespace {

using povray_testing::povray_run;

std::vector<Vec3> random_points(unsigned seed, int count, double lo, double hi) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(lo, hi);
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    points.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  }
  return points;
}

// Random points at several scales, both signs: within a cell of the origin up to 1e6.
std::vector<Vec3> points_at_all_scales() {
  std::vector<Vec3> points;
  unsigned seed = 1;
  for (double scale : {1.0, 10.0, 1000.0, 1e6}) {
    for (const Vec3& p : random_points(seed++, 100, -scale, scale)) points.push_back(p);
  }
  return points;
}

// The scene prints `function_name(point)` for each point, one number a line. Points go in
// with 9 decimals, and the returned points are those numbers, exactly as POV-Ray read them.
std::vector<double> povray_values(const std::string& declarations, const std::string& function,
                                  std::vector<Vec3>& points) {
  std::ostringstream scene;
  scene.precision(9);
  scene << std::fixed << "#version 3.7;\n#include \"functions.inc\"\n" << declarations;
  for (const Vec3& p : points) {
    scene << "#debug concat(str(" << function << "(" << p.x << "," << p.y << "," << p.z
          << "),0,18),\"\\n\")\n";
  }
  for (Vec3& p : points) {
    for (int axis = 0; axis < 3; ++axis) {
      std::ostringstream text;
      text.precision(9);
      text << std::fixed << p[axis];
      p[axis] = std::stod(text.str());
    }
  }
  std::istringstream printed(povray_run(scene.str()).debug);
  std::vector<double> values;
  for (double v; printed >> v;) values.push_back(v);
  return values;
}

TEST(PovRayNoise, MatchesF_noise3dAtRandomPoints) {
  SKIP_WITHOUT_POVRAY();
  std::vector<Vec3> points = points_at_all_scales();
  const std::vector<double> pov = povray_values("", "f_noise3d", points);
  ASSERT_EQ(pov.size(), points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_NEAR(noise(points[k]), pov[k], 1e-12) << "at " << points[k].x << " " << points[k].y
                                                  << " " << points[k].z;
  }
}

TEST(PovRayNoise, GeneratorOneMatchesPovRay) {
  SKIP_WITHOUT_POVRAY();
  std::vector<Vec3> points = random_points(7, 200, -50.0, 50.0);
  const std::vector<double> pov =
      povray_values("#declare G1 = function { f_noise_generator(x, y, z, 1) }\n", "G1", points);
  ASSERT_EQ(pov.size(), points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_NEAR(noise_of_generator(points[k], 1), pov[k], 1e-12);
  }
}

// The turbulence warp displaces a gradient pattern: `gradient x turbulence 0.1` prints
// fract(x + 0.1 D.x). Points stay positive, where POV-Ray's gradient is a plain fract.
TEST(PovRayNoise, TurbulenceWarpMatchesPovRay) {
  SKIP_WITHOUT_POVRAY();
  const char* axes = "xyz";
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<Vec3> points = random_points(20 + axis, 150, 0.5, 300.0);
    const std::string declaration = std::string("#declare W = function { pattern { gradient ") +
                                    axes[axis] +
                                    " turbulence 0.1 octaves 3 omega 0.7 lambda 2.3 } }\n";
    const std::vector<double> pov = povray_values(declaration, "W", points);
    ASSERT_EQ(pov.size(), points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Vec3 displaced = points[k] + 0.1 * turbulence_vector(points[k], 3, 0.7, 2.3);
      const double ours = displaced[axis] - std::floor(displaced[axis]);
      double difference = std::abs(ours - pov[k]);
      difference = std::min(difference, 1.0 - difference);  // 0.9999... against 0.0000...
      EXPECT_LT(difference, 1e-12) << "axis " << axis << " point " << k;
    }
  }
}

// The blend of cubic weights and linear ramps is C1: value and slope agree on both sides of
// a cell face, whatever the tables hold.
TEST(PovRayNoise, ValueAndSlopeContinuousAcrossCellFaces) {
  const double h = 1e-5;
  for (const Vec3& p : random_points(3, 50, -20.0, 20.0)) {
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 face = p;
      face[axis] = std::round(face[axis]);
      Vec3 step(0.0);
      step[axis] = h;
      const double below = noise(face - step), at = noise(face), above = noise(face + step);
      EXPECT_NEAR(below, above, 4.0 * h);
      const double slope_below = (at - below) / h, slope_above = (above - at) / h;
      EXPECT_NEAR(slope_below, slope_above, 1e-3);
    }
  }
}

// POV-Ray's lattice hash repeats every 4096 cells along each axis (measured); ours too.
TEST(PovRayNoise, RepeatsEvery4096Cells) {
  for (const Vec3& p : random_points(4, 50, -100.0, 100.0)) {
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 shifted = p;
      shifted[axis] += 4096.0;
      EXPECT_NEAR(noise(p), noise(shifted), 1e-12);
    }
  }
}

TEST(PovRayNoise, DefaultGeneratorStaysWithinUnitRangeAndVaries) {
  double lo = 1.0, hi = 0.0;
  for (const Vec3& p : random_points(5, 20000, -100.0, 100.0)) {
    const double v = noise(p);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 1.0);
  EXPECT_LT(lo, 0.15);
  EXPECT_GT(hi, 0.85);
}

TEST(PovRayNoise, TurbulenceSumsOctaves) {
  const Vec3 p(0.3, 0.6, 0.9);
  const Vec3 t = turbulence_vector(p, 2, 0.5, 2.0);
  const Vec3 expected = vector_noise(p) + 0.5 * vector_noise(2.0 * p);
  EXPECT_NEAR(glm::length(t - expected), 0.0, 1e-15);
}

}  // namespace
}  // namespace convray::render
