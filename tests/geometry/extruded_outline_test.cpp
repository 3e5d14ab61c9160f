// Extruded outlines (the text object's shape) against analytic answers: a square with a
// square hole and a disc made of quadratic pieces, whose crossings along rays and inside
// points follow from elementary geometry; and the winding rule against a brute-force
// point-in-polygon test of the finely subdivided curves.
#include "geometry/extruded_outline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace convray::geometry {
namespace {

using scene::OutlinePiece;

OutlinePiece line(Vec2 a, Vec2 c) { return {a, 0.5 * (a + c), c}; }

// A closed polygon as straight pieces, in the order given.
std::vector<OutlinePiece> polygon(const std::vector<Vec2>& corners) {
  std::vector<OutlinePiece> pieces;
  for (size_t i = 0; i < corners.size(); ++i) {
    pieces.push_back(line(corners[i], corners[(i + 1) % corners.size()]));
  }
  return pieces;
}

// The unit square (clockwise, as TrueType's outer contours) with a hole of side 0.5 in the
// middle (counter-clockwise).
scene::Text square_with_hole(double thickness) {
  std::vector<OutlinePiece> glyph = polygon({{0, 0}, {0, 1}, {1, 1}, {1, 0}});
  const std::vector<OutlinePiece> hole = polygon({{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75},
                                                  {0.25, 0.75}});
  glyph.insert(glyph.end(), hole.begin(), hole.end());
  return scene::Text{{glyph}, thickness};
}

std::vector<Crossing> crossings_of(const Shape& shape, const Vec3& origin, const Vec3& toward) {
  std::vector<Crossing> out;
  TraceStats stats;
  shape.crossings(Ray{origin, glm::normalize(toward)}, 0.0, 1e9, out, stats);
  return out;
}

TEST(ExtrudedOutlineShape, RayAlongXCrossesTheFourSidesOfASquareWithAHole) {
  const ExtrudedOutlineShape shape(square_with_hole(0.4).glyphs, ExtrusionAxes{0, 1, 2, 0.0, 0.4}, nullptr);
  const auto hits = crossings_of(shape, Vec3(-1.0, 0.5, 0.2), Vec3(1, 0, 0));
  ASSERT_EQ(hits.size(), 4u);
  const double expected[4] = {1.0, 1.25, 1.75, 2.0};
  const double normal_x[4] = {-1.0, 1.0, -1.0, 1.0};  // out of the solid each time
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(hits[size_t(i)].t, expected[i], 1e-12);
    EXPECT_NEAR(hits[size_t(i)].normal.x, normal_x[i], 1e-12);
  }
  // Above the extrusion the ray meets nothing.
  EXPECT_TRUE(crossings_of(shape, Vec3(-1.0, 0.5, 0.5), Vec3(1, 0, 0)).empty());
}

TEST(ExtrudedOutlineShape, RayAlongZMeetsTheCapsWhereTheOutlineWinds) {
  const ExtrudedOutlineShape shape(square_with_hole(0.4).glyphs, ExtrusionAxes{0, 1, 2, 0.0, 0.4}, nullptr);
  const auto solid = crossings_of(shape, Vec3(0.1, 0.1, -3.0), Vec3(0, 0, 1));
  ASSERT_EQ(solid.size(), 2u);
  EXPECT_NEAR(solid[0].t, 3.0, 1e-12);
  EXPECT_NEAR(solid[0].normal.z, -1.0, 0.0);
  EXPECT_NEAR(solid[1].t, 3.4, 1e-12);
  EXPECT_NEAR(solid[1].normal.z, 1.0, 0.0);
  EXPECT_TRUE(crossings_of(shape, Vec3(0.5, 0.5, -3.0), Vec3(0, 0, 1)).empty());  // the hole
  EXPECT_TRUE(shape.inside(Vec3(0.1, 0.9, 0.2)));
  EXPECT_FALSE(shape.inside(Vec3(0.5, 0.5, 0.2)));
  EXPECT_FALSE(shape.inside(Vec3(0.1, 0.9, 0.5)));
}

// A disc of radius 1 from four quadratic pieces through the points at 0, 90, 180, 270
// degrees, each with the control point where the tangents meet: a rational-free
// approximation whose exact curve is known, x(s), y(s) per piece.
std::vector<OutlinePiece> rounded_diamond() {
  // Clockwise: up the left, across the top, down the right, back along the bottom.
  return {{{-1, 0}, {-1, 1}, {0, 1}},
          {{0, 1}, {1, 1}, {1, 0}},
          {{1, 0}, {1, -1}, {0, -1}},
          {{0, -1}, {-1, -1}, {-1, 0}}};
}

// Inside test by brute force: the curves cut into 2,000 straight pieces each, then the
// even-odd crossing count of a polygon (the shape is simple, so even-odd = nonzero).
bool inside_polygon(const std::vector<OutlinePiece>& pieces, const Vec2& p) {
  std::vector<Vec2> corners;
  for (const OutlinePiece& piece : pieces) {
    for (int k = 0; k < 2000; ++k) {
      const double s = k / 2000.0;
      corners.push_back((1 - s) * (1 - s) * piece.a + 2 * s * (1 - s) * piece.b + s * s * piece.c);
    }
  }
  bool inside = false;
  for (size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++) {
    const Vec2 a = corners[i], b = corners[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
      inside = !inside;
    }
  }
  return inside;
}

TEST(ExtrudedOutlineShape, WindingOfCurvedPiecesAgreesWithASubdividedPolygon) {
  const std::vector<OutlinePiece> pieces = rounded_diamond();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.2, 1.2);
  int inside = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec2 p(coordinate(random), coordinate(random));
    const bool expected = inside_polygon(pieces, p);
    EXPECT_EQ(outline_winding(pieces, p) != 0, expected) << p.x << ", " << p.y;
    inside += expected;
  }
  EXPECT_GT(inside, 500);  // both answers were tested
}

TEST(ExtrudedOutlineShape, SideCrossingsOfACurveLieOnTheCurve) {
  // Rays in the plane z = 0.3 towards the middle: each side crossing is where the ray meets
  // the quadratic piece, so the point must satisfy the piece's implicit form. For the first
  // piece (-1,0) (-1,1) (0,1): x = -1 + s^2, y = 2 s - s^2, i.e. (x + 1) = (1 - (1 - y))^...
  // checked numerically: the nearest point of the densely sampled piece lies within 1e-6.
  const ExtrudedOutlineShape shape({rounded_diamond()}, ExtrusionAxes{0, 1, 2, 0.0, 1.0}, nullptr);
  for (int k = 0; k < 50; ++k) {
    const double angle = 2.0 * kPi * k / 50.0;
    const Vec3 origin(3.0 * std::cos(angle), 3.0 * std::sin(angle), 0.3);
    const auto hits = crossings_of(shape, origin, Vec3(-origin.x, -origin.y, 0.0));
    ASSERT_EQ(hits.size(), 2u) << k;
    const Vec3 p = origin + hits[0].t * glm::normalize(Vec3(-origin.x, -origin.y, 0.0));
    double nearest = 1e9;
    for (const OutlinePiece& piece : rounded_diamond()) {
      for (int j = 0; j <= 20000; ++j) {
        const double s = j / 20000.0;
        const Vec2 q = (1 - s) * (1 - s) * piece.a + 2 * s * (1 - s) * piece.b + s * s * piece.c;
        nearest = std::min(nearest, glm::length(q - Vec2(p)));
      }
    }
    EXPECT_LT(nearest, 1e-4) << k;
    // The normal points away from the middle.
    EXPECT_GT(glm::dot(hits[0].normal, Vec3(p.x, p.y, 0.0)), 0.0) << k;
  }
}

TEST(ExtrudedOutlineShape, PrismsAreInsideWhereAnOddNumberOfPolygonsEncloseAPoint) {
  // Two overlapping squares in the xz plane, both counter-clockwise, extruded along y from
  // -1 to 2: their overlap [1, 2] x [1, 2] is outside, as in POV-Ray's prisms.
  std::vector<OutlinePiece> pieces = polygon({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  const std::vector<OutlinePiece> second = polygon({{1, 1}, {3, 1}, {3, 3}, {1, 3}});
  pieces.insert(pieces.end(), second.begin(), second.end());
  const ExtrudedOutlineShape shape({pieces}, ExtrusionAxes{0, 2, 1, -1.0, 2.0, true}, nullptr);
  EXPECT_TRUE(shape.inside(Vec3(0.5, 0.0, 0.5)));
  EXPECT_FALSE(shape.inside(Vec3(1.5, 0.0, 1.5)));
  EXPECT_TRUE(shape.inside(Vec3(2.5, 1.9, 2.5)));
  EXPECT_FALSE(shape.inside(Vec3(0.5, 2.1, 0.5)));
  // Along x at z = 1.5: in at 0, out at 1 (into the overlap), in at 2, out at 3; normals out
  // of the solid whatever the polygons' orientation.
  const auto hits = crossings_of(shape, Vec3(-1.0, 0.0, 1.5), Vec3(1, 0, 0));
  ASSERT_EQ(hits.size(), 4u);
  const double expected[4] = {1.0, 2.0, 3.0, 4.0};
  const double normal_x[4] = {-1.0, 1.0, -1.0, 1.0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(hits[size_t(i)].t, expected[i], 1e-12);
    EXPECT_NEAR(hits[size_t(i)].normal.x, normal_x[i], 1e-12);
  }
  // Down along y: the caps at y = 2 (normal +y) and y = -1 (normal -y).
  const auto caps = crossings_of(shape, Vec3(0.5, 5.0, 0.5), Vec3(0, -1, 0));
  ASSERT_EQ(caps.size(), 2u);
  EXPECT_NEAR(caps[0].t, 3.0, 1e-12);
  EXPECT_EQ(caps[0].normal.y, 1.0);
  EXPECT_NEAR(caps[1].t, 6.0, 1e-12);
  EXPECT_EQ(caps[1].normal.y, -1.0);
}

}  // namespace
}  // namespace convray::geometry
