// convray's `convolution { }`: defaults, offset -> threshold, each component kind with its
// transforms and texture, triangle grouping, meshes loaded from files, and every error.
#include <filesystem>
#include <fstream>

#include "field/threshold.hpp"
#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;
using Kind = scene::Implicit::Kind;

scene::Implicit convolution_of(const ParseResult& result) {
  return shape_of<scene::Implicit>(only_object(result));
}

TEST(ItemsConvolution, DefaultsGiveOffsetHalfTheRadius) {
  const auto& c = convolution_of(parse("convolution { segment { <0,0,0>, <1,0,0> } }"));
  EXPECT_FALSE(c.is_blob);
  ASSERT_EQ(c.object.segments.size(), 1u);
  EXPECT_EQ(c.object.segments[0].weight.strength, 1.0);
  EXPECT_EQ(c.object.segments[0].weight.radius, 1.0);
  expect_near(c.object.segments[0].segment.b, Vec3(1, 0, 0));
  // The plane's field at d = R/2 with s = R = 1: (pi/3) (1 - 1/4)^3.
  EXPECT_NEAR(c.object.threshold, kPi / 3.0 * 0.421875, 1e-15);
}

TEST(ItemsConvolution, OffsetAndThreshold) {
  const auto& offset =
      convolution_of(parse("convolution { radius 2 strength 3 offset 0.5 point { 0 } }"));
  // s (pi/3) (R^2 - d^2)^3 / R^4 = 3 (pi/3) (3.75)^3 / 16.
  EXPECT_NEAR(offset.object.threshold, kPi * 3.75 * 3.75 * 3.75 / 16.0, 1e-12);
  EXPECT_DOUBLE_EQ(offset.object.threshold, field::threshold_for_offset(3, 2, 0.5));
  EXPECT_EQ(offset.object.points[0].weight.radius, 2.0);
  EXPECT_EQ(offset.object.points[0].weight.strength, 3.0);
  const auto& raw = convolution_of(parse("convolution { threshold 0.8 point { 0 } }"));
  EXPECT_EQ(raw.object.threshold, 0.8);
}

TEST(ItemsConvolution, DefaultsGivenAfterTheComponentsStillApply) {
  const auto& c = convolution_of(
      parse("convolution { point { 0 } point { x radius 0.25 strength -1 } radius 0.5 }"));
  EXPECT_EQ(c.object.points[0].weight.radius, 0.5);
  EXPECT_EQ(c.object.points[1].weight.radius, 0.25);
  EXPECT_EQ(c.object.points[1].weight.strength, -1.0);
}

TEST(ItemsConvolution, ComponentTransformsMoveTheSkeletonAndScaleTheRadius) {
  const auto& c = convolution_of(parse(R"(
    convolution {
      radius 0.5
      point { <1, 0, 0> scale 2 translate y }
      segment { 0, x rotate 90*y }
      arc { <1, 0, 0>, <0, 1, 0>, <-1, 0, 0> translate z }
    })"));
  expect_near(c.object.points[0].center, Vec3(2, 1, 0));
  EXPECT_DOUBLE_EQ(c.object.points[0].weight.radius, 1.0);
  expect_near(c.object.segments[0].segment.b, Vec3(0, 0, -1));
  EXPECT_EQ(c.object.segments[0].weight.radius, 0.5);
  const field::Arc& arc = c.object.arcs[0].arc;
  expect_near(arc.center, Vec3(0, 0, 1), 1e-12);
  EXPECT_NEAR(arc.radius, 1.0, 1e-12);
  EXPECT_NEAR(arc.angle, kPi, 1e-12);
  expect_near(arc.point_at(0.0), Vec3(1, 0, 1), 1e-12);
  expect_near(arc.point_at(arc.angle / 2), Vec3(0, 1, 1), 1e-12);
}

TEST(ItemsConvolution, ConsecutiveTrianglesOfEqualWeightShareOneMesh) {
  const auto& c = convolution_of(parse(R"(
    convolution {
      triangle { 0, x, y }
      triangle { x, y, <1, 1, 0> }
      triangle { 0, x, z strength 2 }
      point { 0 }
      triangle { 0, y, z }
    })"));
  ASSERT_EQ(c.object.meshes.size(), 3u);
  EXPECT_EQ(c.object.meshes[0].triangles.size(), 2u);
  EXPECT_EQ(c.object.meshes[1].triangles.size(), 1u);
  EXPECT_EQ(c.object.meshes[1].weight.strength, 2.0);
  EXPECT_EQ(c.object.meshes[2].triangles.size(), 1u);  // the point broke the run
  const std::vector<std::pair<Kind, size_t>> order = {
      {Kind::mesh, 0}, {Kind::mesh, 1}, {Kind::point, 0}, {Kind::mesh, 2}};
  EXPECT_EQ(c.component_order, order);
}

TEST(ItemsConvolution, ComponentTexturesAndObjectModifiers) {
  const auto object = only_object(parse(R"(
    convolution {
      segment { 0, x }
      point { y pigment { rgb <1, 0, 0> } normal { bumps 0.5 } }
      texture { pigment { rgb 1 } }
      scale 2
    })"));
  const auto& c = shape_of<scene::Implicit>(object);
  ASSERT_EQ(c.component_textures.size(), 1u);
  EXPECT_EQ(c.component_textures[0].index, 1u);
  expect_near(c.component_textures[0].texture->pigment.color.rgb, Vec3(1, 0, 0));
  // A texture with a pattern moves with the object (one that looks the same everywhere is
  // shared unmoved: scene/moved_textures.hpp).
  expect_near(c.component_textures[0].texture->pigment.space.transform.point(Vec3(1.0)), Vec3(2.0));
  expect_near(object->transform.point(Vec3(1.0)), Vec3(2.0));
}

// A unit square (one quad: two triangles) written as OBJ into a fresh folder.
std::filesystem::path write_square(const std::string& folder_name) {
  const auto folder = std::filesystem::temp_directory_path() / folder_name;
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "square.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  return folder;
}

TEST(ItemsConvolution, MeshFromAnObjFile) {
  const auto folder = write_square("convray_items_mesh_test");
  const std::string path = (folder / "square.obj").string();
  const auto& c = convolution_of(
      parse("convolution { radius 0.5 mesh { \"" + path + "\" strength 2 scale 2 } }",
            reading_from(folder.string())));
  ASSERT_EQ(c.object.meshes.size(), 1u);
  const scene::MeshComponent& mesh = c.object.meshes[0];
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.weight.strength, 2.0);
  EXPECT_DOUBLE_EQ(mesh.weight.radius, 1.0);
  Box3 bounds;
  for (const field::Triangle& t : mesh.triangles) {
    for (const Vec3& p : {t.a, t.b, t.c}) bounds.extend(p);
  }
  expect_near(bounds.lo, Vec3(0.0));
  expect_near(bounds.hi, Vec3(2, 2, 0));
  // The threshold follows the object's defaults (strength 1, radius 0.5, offset 0.25).
  EXPECT_DOUBLE_EQ(c.object.threshold, field::threshold_for_offset(1, 0.5, 0.25));
  std::filesystem::remove_all(folder);
}

TEST(ItemsConvolution, MeshNamedRelativeToTheSceneFile) {
  const auto folder = write_square("convray_items_scene_test");
  std::ofstream(folder / "scene.pov") << "convolution { mesh { \"square.obj\" } }\n";
  const auto result = parse_file((folder / "scene.pov").string(), ParseOptions{});
  EXPECT_EQ(convolution_of(result).object.meshes[0].triangles.size(), 2u);
  std::filesystem::remove_all(folder);
}

TEST(ItemsConvolution, MeshLoadErrorsPointAtTheMeshKeyword) {
  const auto folder = std::filesystem::temp_directory_path() / "convray_items_bad_mesh";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "bad.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  const std::string bad = (folder / "bad.obj").string();
  const ParseFailure failure =
      parse_error("convolution {\n  mesh { \"" + bad + "\" } }", reading_from(folder.string()));
  EXPECT_EQ(failure.loc.line, 2);
  EXPECT_EQ(failure.loc.column, 3);
  EXPECT_NE(failure.message.find("cannot load mesh"), std::string::npos) << failure.message;
  const ParseFailure missing = parse_error("convolution {\n  mesh { \"no_such_file.obj\" } }");
  EXPECT_EQ(missing.loc.line, 2);
  EXPECT_EQ(missing.loc.column, 3);
  std::filesystem::remove_all(folder);
}

TEST(ItemsConvolution, Errors) {
  EXPECT_TRUE(fails_with("convolution { radius 0 point { 0 } }", 1, 15,
                         "convolution radius must be positive"));
  EXPECT_TRUE(fails_with("convolution { point { 0 radius -1 } }", 1, 25,
                         "convolution point radius must be positive"));
  EXPECT_TRUE(fails_with("convolution { offset 1 point { 0 } }", 1, 15,
                         "0 <= offset < radius (offset 1, radius 1)"));
  EXPECT_TRUE(fails_with("convolution { threshold -2 point { 0 } }", 1, 15,
                         "convolution threshold must be positive"));
  EXPECT_TRUE(fails_with("convolution { offset 0.1 threshold 2 point { 0 } }", 1, 26,
                         "give either offset or threshold, not both"));
  EXPECT_TRUE(fails_with("convolution { arc { 0, x, 2*x } }", 1, 15, "collinear"));
  EXPECT_TRUE(fails_with("convolution { segment { x, x } }", 1, 15, "end points coincide"));
  EXPECT_TRUE(fails_with("convolution { triangle { 0, x, 2*x } }", 1, 15, "collinear"));
  EXPECT_TRUE(fails_with("convolution { }", 1, 1, "convolution has no components"));
  EXPECT_TRUE(fails_with("convolution { point { 0 scale <1, 1, 2> } }", 1, 25,
                         "non-uniform scale (or shear) of a convolution point"));
  EXPECT_TRUE(fails_with("convolution { point { 0 } translate x point { x } }", 1, 39,
                         "the convolution's components must come before"));
  EXPECT_TRUE(fails_with("convolution { piont { 0 } }", 1, 15, "did you mean 'point'?"));
  EXPECT_TRUE(
      fails_with("convolution { point { 0 strenght 2 } }", 1, 25, "did you mean 'strength'?"));
  EXPECT_TRUE(
      fails_with("convolution { strength -1 point { 0 } }", 1, 15, "needs a positive strength"));
}

}  // namespace
}  // namespace convray::sdl
