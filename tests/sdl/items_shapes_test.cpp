// The classic primitives: their parameters land in the records, degenerate ones fail at the
// object's keyword, and typos, wrong types and missing braces are reported where they are.
#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;

TEST(ItemsShapes, SphereCenterRadiusAndLocation) {
  const auto object = only_object(parse("\n  sphere { <1, 2, 3>, 0.5 }"));
  const auto& sphere = shape_of<scene::Sphere>(object);
  expect_near(sphere.center, Vec3(1, 2, 3));
  EXPECT_EQ(sphere.radius, 0.5);
  EXPECT_EQ(object->loc.line, 2);
  EXPECT_EQ(object->loc.column, 3);
  // No texture of its own: POV-Ray's default texture (a black pigment) at the top level.
  ASSERT_NE(object->texture, nullptr);
  EXPECT_EQ(object->texture->pigment.color.rgb, Vec3(0.0));
}

TEST(ItemsShapes, SphereWithoutCommaAndFloatCenter) {
  const auto& sphere = shape_of<scene::Sphere>(only_object(parse("sphere { 1 2 }")));
  expect_near(sphere.center, Vec3(1, 1, 1));  // a float promotes to <f, f, f>
  EXPECT_EQ(sphere.radius, 2.0);
}

TEST(ItemsShapes, Box) {
  const auto& box = shape_of<scene::Box>(only_object(parse("box { <-1, 0, 2>, <3, 0, 5> }")));
  expect_near(box.corner1, Vec3(-1, 0, 2));
  expect_near(box.corner2, Vec3(3, 0, 5));  // zero extent along y is fine
}

TEST(ItemsShapes, Plane) {
  const auto& plane = shape_of<scene::Plane>(only_object(parse("plane { y, -1 }")));
  expect_near(plane.normal, Vec3(0, 1, 0));
  EXPECT_EQ(plane.distance, -1.0);
}

TEST(ItemsShapes, CylinderOpenOrClosed) {
  const auto closed = parse("cylinder { <0,0,0>, <0,2,0>, 0.5 }");
  const auto& c = shape_of<scene::Cylinder>(only_object(closed));
  expect_near(c.base, Vec3(0.0));
  expect_near(c.cap, Vec3(0, 2, 0));
  EXPECT_EQ(c.radius, 0.5);
  EXPECT_FALSE(c.open);
  const auto open = parse("cylinder { 0, y, 1 pigment { rgb 1 } open }");
  EXPECT_TRUE(shape_of<scene::Cylinder>(only_object(open)).open);
}

TEST(ItemsShapes, Cone) {
  const auto& cone =
      shape_of<scene::Cone>(only_object(parse("cone { <0,0,0>, 1, <0,3,0>, 0 open }")));
  EXPECT_EQ(cone.base_radius, 1.0);
  EXPECT_EQ(cone.cap_radius, 0.0);
  expect_near(cone.cap, Vec3(0, 3, 0));
  EXPECT_TRUE(cone.open);
}

TEST(ItemsShapes, Torus) {
  const auto& torus = shape_of<scene::Torus>(only_object(parse("torus { 2, 0.5 sturm }")));
  EXPECT_EQ(torus.major, 2.0);
  EXPECT_EQ(torus.minor, 0.5);
}

TEST(ItemsShapes, DiscWithAndWithoutHole) {
  const auto& plain = shape_of<scene::Disc>(only_object(parse("disc { <0,1,0>, y, 2 }")));
  EXPECT_EQ(plain.radius, 2.0);
  EXPECT_EQ(plain.hole_radius, 0.0);
  const auto& holed = shape_of<scene::Disc>(only_object(parse("disc { 0, z, 2, 0.5 }")));
  expect_near(holed.normal, Vec3(0, 0, 1));
  EXPECT_EQ(holed.hole_radius, 0.5);
}

TEST(ItemsShapes, TriangleAndSmoothTriangle) {
  const auto& flat = shape_of<scene::TriangleMesh>(only_object(parse("triangle { 0, x, y }")));
  ASSERT_EQ(flat.faces.size(), 1u);
  expect_near(flat.vertices[size_t(flat.faces[0].vertices[1])], Vec3(1, 0, 0));
  EXPECT_EQ(flat.faces[0].normals[0], -1);
  const auto& smooth = shape_of<scene::TriangleMesh>(
      only_object(parse("smooth_triangle { 0, <0,0,-1>, x, <1,0,-1>, y, <0,1,-1> }")));
  ASSERT_EQ(smooth.faces.size(), 1u);
  expect_near(smooth.normals[size_t(smooth.faces[0].normals[1])], Vec3(1, 0, -1));
}

TEST(ItemsShapes, DegenerateShapesFailAtTheirKeyword) {
  EXPECT_TRUE(fails_with("sphere { 0, -1 }", 1, 1, "sphere radius must be positive"));
  EXPECT_TRUE(fails_with("\n cylinder { 0, 0, 1 }", 2, 2, "end points coincide"));
  EXPECT_TRUE(fails_with("cone { 0, 0, y, 0 }", 1, 1, "both radii are 0"));
  EXPECT_TRUE(fails_with("cone { 0, -1, y, 0 }", 1, 1, "must not be negative"));
  EXPECT_TRUE(fails_with("torus { 1, 0 }", 1, 1, "torus minor radius must be positive"));
  EXPECT_TRUE(fails_with("plane { 0, 1 }", 1, 1, "plane normal must not be <0, 0, 0>"));
  EXPECT_TRUE(fails_with("disc { 0, y, 1, 2 }", 1, 1, "hole radius"));
  EXPECT_TRUE(fails_with("triangle { 0, x, 2*x }", 1, 1, "collinear"));
}

TEST(ItemsShapes, MisspelledKeywordSuggestsTheRightOne) {
  EXPECT_TRUE(fails_with("sphere { 0, 1 texure { } }", 1, 15,
                         "unexpected 'texure' in sphere (did you mean 'texture'?)"));
  EXPECT_TRUE(fails_with("sphere { 0, 1\n  tranlate x }", 2, 3, "did you mean 'translate'?"));
  EXPECT_TRUE(fails_with("cylinder { 0, y, 1 opne }", 1, 20, "did you mean 'open'?"));
}

TEST(ItemsShapes, WrongValueTypeNamesTheParameter) {
  EXPECT_TRUE(
      fails_with("sphere { 0, <1, 2, 3> }", 1, 13, "expected a float for radius, found a vector"));
  EXPECT_TRUE(fails_with("sphere { 0, }", 1, 13, "expected a float for radius, found '}'"));
  EXPECT_TRUE(
      fails_with("torus { 1, \"a\" }", 1, 12, "expected a float for minor radius, found a string"));
}

TEST(ItemsShapes, MissingBraceNamesTheBlockAndWhereItOpened) {
  const ParseFailure failure = parse_error("sphere { 0, 1\n  pigment { rgb 1 }\n");
  EXPECT_NE(failure.message.find("missing '}' to close the sphere opened at test.pov:1:1"),
            std::string::npos)
      << failure.message;
  // A block that runs into the next statement says that its '}' may be missing.
  EXPECT_TRUE(fails_with("sphere { 0, 1\nsphere { 0, 2 }", 2, 1,
                         "is the '}' of the sphere at test.pov:1:1 missing?"));
}

TEST(ItemsShapes, UnknownTopLevelWord) {
  EXPECT_TRUE(fails_with("sphare { 0, 1 }", 1, 1, "did you mean 'sphere'?"));
  EXPECT_TRUE(fails_with("#declare Ball = sphere { 0, 1 }\nBall", 2, 1,
                         "'Ball' is an object: place it with object { Ball }"));
}

}  // namespace
}  // namespace convray::sdl
