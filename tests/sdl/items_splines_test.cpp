// The splines of lathe and prism as polynomial pieces: each piece passes through the points
// POV-Ray's documentation names (the first point of a quadratic or cubic spline only sets a
// slope), and prisms split their points into closed outlines by each spline's rule.
#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;

Vec2 start_of(const scene::SplinePiece& piece) { return piece.c[0]; }
Vec2 end_of(const scene::SplinePiece& piece) {
  return piece.c[0] + piece.c[1] + piece.c[2] + piece.c[3];
}
Vec2 slope_at_start(const scene::SplinePiece& piece) { return piece.c[1]; }

TEST(ItemsSplines, LatheSplinesRunThroughTheirPoints) {
  const char* points = "<1, 0>, <2, 1>, <1.5, 2>, <3, 3>, <1, 4>";
  const auto& linear =
      shape_of<scene::Lathe>(only_object(parse(std::string("lathe { 5, ") + points + " }")));
  ASSERT_EQ(linear.pieces.size(), 4u);  // linear_spline is the default
  expect_near(Vec3(end_of(linear.pieces[3]), 0), Vec3(1, 4, 0));
  const auto& quadratic = shape_of<scene::Lathe>(
      only_object(parse(std::string("lathe { quadratic_spline 5, ") + points + " }")));
  ASSERT_EQ(quadratic.pieces.size(), 3u);  // from the second point on
  expect_near(Vec3(start_of(quadratic.pieces[0]), 0), Vec3(2, 1, 0));
  expect_near(Vec3(end_of(quadratic.pieces[0]), 0), Vec3(1.5, 2, 0));
  // The parabola through the previous point: its slope at the start is (P2 - P0) / 2.
  expect_near(Vec3(slope_at_start(quadratic.pieces[0]), 0), Vec3(0.25, 1, 0));
  const auto& cubic = shape_of<scene::Lathe>(
      only_object(parse(std::string("lathe { cubic_spline 5, ") + points + " }")));
  ASSERT_EQ(cubic.pieces.size(), 2u);  // between the second and the last but one point
  expect_near(Vec3(start_of(cubic.pieces[1]), 0), Vec3(1.5, 2, 0));
  expect_near(Vec3(end_of(cubic.pieces[1]), 0), Vec3(3, 3, 0));
  expect_near(Vec3(slope_at_start(cubic.pieces[1]), 0), Vec3(0.5, 1, 0));
  EXPECT_TRUE(fails_with("lathe { bezier_spline 5, " + std::string(points) + " }", 1, 23,
                         "a bezier_spline needs a multiple of 4 points"));
  EXPECT_TRUE(fails_with("lathe { cubic_spline 3, <0, 0>, <1, 1>, <0, 2> }", 1, 22,
                         "a cubic_spline needs at least 4 points"));
}

TEST(ItemsSplines, PrismOutlinesCloseByEachSplinesRule) {
  // Two squares per spline, each closed where its first point on the curve comes again.
  const auto pieces = [](const std::string& text) {
    const auto& prism = shape_of<scene::Prism>(only_object(parse(text)));
    std::vector<size_t> counts;
    for (const auto& outline : prism.polygons) counts.push_back(outline.size());
    return counts;
  };
  EXPECT_EQ(pieces("prism { quadratic_spline 0, 1, 12, <0, 1>, <0, 0>, <1, 0>, <1, 1>, <0, 1>,"
                   " <0, 0>, <2, 3>, <2, 2>, <3, 2>, <3, 3>, <2, 3>, <2, 2> }"),
            (std::vector<size_t>{4, 4}));
  EXPECT_EQ(pieces("prism { cubic_spline 0, 1, 14, <0, 1>, <0, 0>, <1, 0>, <1, 1>, <0, 1>,"
                   " <0, 0>, <1, 0>, <2, 3>, <2, 2>, <3, 2>, <3, 3>, <2, 3>, <2, 2>, <3, 2> }"),
            (std::vector<size_t>{4, 4}));
  EXPECT_EQ(pieces("prism { bezier_spline 0, 1, 8, <0, 0>, <1, 0>, <1, 1>, <1, 1>,"
                   " <1, 1>, <0, 1>, <0, 1>, <0, 0> }"),
            (std::vector<size_t>{2}));
  const auto& conic = shape_of<scene::Prism>(
      only_object(parse("prism { conic_sweep linear_spline 1, 0.2, 4, <0, 0>, <1, 0>, <0, 1>,"
                        " <0, 0> }")));
  EXPECT_TRUE(conic.conic);
  EXPECT_EQ(conic.height1, 0.2);
  EXPECT_EQ(conic.height2, 1.0);
}

}  // namespace
}  // namespace convray::sdl
