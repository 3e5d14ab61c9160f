// POV-Ray's blob: the component forms, component transforms and textures, and POV-Ray's own
// sample blob scenes parsed unmodified.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;
using Kind = scene::Implicit::Kind;

scene::Implicit blob_of(const scene::ObjectPtr& object) {
  return shape_of<scene::Implicit>(object);
}

TEST(ItemsBlob, ThreeComponentForms) {
  const auto object = only_object(parse(R"(
    blob {
      threshold 0.6
      sphere { <1, 0, 0>, 2, 3 }
      sphere { <0, 1, 0>, 1.5, strength -1 }
      cylinder { <0, 0, 0>, <0, 0, 4>, 0.5, strength 2 }
      component 0.5, 1.25, <0, 0, 9>
    })"));
  const scene::Implicit& blob = blob_of(object);
  EXPECT_TRUE(blob.is_blob);
  EXPECT_EQ(blob.object.threshold, 0.6);
  ASSERT_EQ(blob.object.blob_spheres.size(), 3u);
  ASSERT_EQ(blob.object.blob_cylinders.size(), 1u);
  const auto& first = blob.object.blob_spheres[0];
  expect_near(first.center, Vec3(1, 0, 0));
  EXPECT_EQ(first.weight.radius, 2.0);
  EXPECT_EQ(first.weight.strength, 3.0);
  EXPECT_EQ(blob.object.blob_spheres[1].weight.strength, -1.0);
  const auto& cylinder = blob.object.blob_cylinders[0];
  expect_near(cylinder.apex, Vec3(0, 0, 4));
  EXPECT_EQ(cylinder.weight.radius, 0.5);
  EXPECT_EQ(cylinder.weight.strength, 2.0);
  const auto& old = blob.object.blob_spheres[2];
  EXPECT_EQ(old.weight.strength, 0.5);
  EXPECT_EQ(old.weight.radius, 1.25);
  expect_near(old.center, Vec3(0, 0, 9));
  // Listing order, all kinds together.
  const std::vector<std::pair<Kind, size_t>> order = {{Kind::blob_sphere, 0},
                                                      {Kind::blob_sphere, 1},
                                                      {Kind::blob_cylinder, 0},
                                                      {Kind::blob_sphere, 2}};
  EXPECT_EQ(blob.component_order, order);
  EXPECT_TRUE(blob.component_textures.empty());
}

TEST(ItemsBlob, DefaultThresholdIsOne) {
  EXPECT_EQ(blob_of(only_object(parse("blob { sphere { 0, 1, 1 } }"))).object.threshold, 1.0);
}

TEST(ItemsBlob, ComponentTransformsMoveCentresAndScaleRadii) {
  const auto object = only_object(parse(R"(
    blob {
      sphere { <1, 0, 0>, 1, 1 rotate 90*y scale 2 translate <0, 1, 0> }
      cylinder { 0, x, 0.5, 1 scale 3 }
    })"));
  const scene::Implicit& blob = blob_of(object);
  expect_near(blob.object.blob_spheres[0].center, Vec3(0, 1, -2));
  EXPECT_DOUBLE_EQ(blob.object.blob_spheres[0].weight.radius, 2.0);
  EXPECT_EQ(blob.object.blob_spheres[0].weight.strength, 1.0);  // strength is not scaled
  expect_near(blob.object.blob_cylinders[0].apex, Vec3(3, 0, 0));
  EXPECT_DOUBLE_EQ(blob.object.blob_cylinders[0].weight.radius, 1.5);
}

TEST(ItemsBlob, NonUniformComponentScaleFailsClearly) {
  EXPECT_TRUE(fails_with("blob { sphere { 0, 1, 1 scale <1, 2, 1> } }", 1, 25,
                         "non-uniform scale (or shear) of a blob sphere is not supported yet"));
}

TEST(ItemsBlob, ComponentTexturesAreIndexedInListingOrder) {
  const auto object = only_object(parse(R"(
    blob {
      sphere { 0, 1, 1 }
      cylinder { 0, y, 1, 1 pigment { rgb <1, 0, 0> } normal { bumps 0.5 } translate x }
      sphere { x, 1, 1 texture { pigment { rgb <0, 0, 1> } normal { bumps 0.5 } } }
      pigment { rgb 1 }
      translate <0, 0, 5>
    })"));
  const scene::Implicit& blob = blob_of(object);
  ASSERT_EQ(blob.component_textures.size(), 2u);
  EXPECT_EQ(blob.component_textures[0].index, 1u);
  EXPECT_EQ(blob.component_textures[1].index, 2u);
  EXPECT_EQ(blob.component_order[1].first, Kind::blob_cylinder);
  const scene::Texture& red = *blob.component_textures[0].texture;
  expect_near(red.pigment.color.rgb, Vec3(1, 0, 0));
  // Moved by the component's translate and then by the blob's (textures with a pattern: one
  // that looks the same everywhere is shared unmoved, scene/moved_textures.hpp).
  expect_near(red.pigment.space.transform.point(Vec3(0.0)), Vec3(1, 0, 5));
  expect_near(blob.component_textures[1].texture->pigment.space.transform.point(Vec3(0.0)),
              Vec3(0, 0, 5));
  expect_near(object->texture->pigment.color.rgb, Vec3(1.0));
}

TEST(ItemsBlob, Errors) {
  EXPECT_TRUE(fails_with("blob { threshold 0 sphere { 0, 1, 1 } }", 1, 8,
                         "blob threshold must be positive"));
  EXPECT_TRUE(fails_with("blob { sphere { 0, -1, 1 } }", 1, 8, "radius must be positive"));
  EXPECT_TRUE(fails_with("blob { }", 1, 1, "blob has no components"));
  EXPECT_TRUE(fails_with("blob { sphere { 0, 1, 1 } scale 2 sphere { x, 1, 1 } }", 1, 35,
                         "the blob's components must come before the object's modifiers"));
  EXPECT_TRUE(
      fails_with("blob { sphere { 0, 1, 1 } treshold 0.5 }", 1, 27, "did you mean 'threshold'?"));
  EXPECT_TRUE(fails_with("blob { cylinder { x, x, 1, 1 } }", 1, 8, "end points coincide"));
}

// --- POV-Ray's sample blob scenes, parsed as they ship.

std::string sample_text(const std::string& name) {
  const std::string path = "/usr/share/povray-3.7/scenes/objects/" + name;
  std::ifstream in(path);
  if (!in) return {};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

const scene::Implicit* only_blob(const ParseResult& result) {
  for (const scene::ObjectPtr& object : result.scene.objects) {
    if (const auto* implicit = std::get_if<scene::Implicit>(&object->shape)) return implicit;
  }
  ADD_FAILURE() << "no blob in the scene";
  return nullptr;
}

#define SKIP_IF_MISSING(text) \
  if ((text).empty()) GTEST_SKIP() << "POV-Ray's sample scenes are not installed"

TEST(ItemsBlobSamples, BlobPov) {
  const std::string text = sample_text("blob.pov");
  SKIP_IF_MISSING(text);
  const auto result = parse_string(text, "blob.pov", ParseOptions{});
  const scene::Implicit* blob = only_blob(result);
  ASSERT_NE(blob, nullptr);
  EXPECT_EQ(blob->object.threshold, 0.6);
  ASSERT_EQ(blob->object.blob_spheres.size(), 3u);  // three `component 1.0, 1.0, <...>`
  for (const auto& sphere : blob->object.blob_spheres) {
    EXPECT_EQ(sphere.weight.strength, 1.0);
    EXPECT_EQ(sphere.weight.radius, 1.0);
  }
  expect_near(blob->object.blob_spheres[1].center, Vec3(-0.375, 0.64952, 0));
  EXPECT_EQ(result.scene.lights.size(), 2u);
}

TEST(ItemsBlobSamples, Blob1a) {
  const std::string text = sample_text("blob1a.pov");
  SKIP_IF_MISSING(text);
  const scene::Implicit* blob = only_blob(parse_string(text, "blob1a.pov", ParseOptions{}));
  ASSERT_NE(blob, nullptr);
  EXPECT_EQ(blob->object.threshold, 0.5);
  ASSERT_EQ(blob->object.blob_cylinders.size(), 2u);
  EXPECT_EQ(blob->object.blob_cylinders[1].weight.radius, 4.0);
  EXPECT_EQ(blob->object.blob_cylinders[1].weight.strength, 2.0);
  ASSERT_EQ(blob->object.blob_spheres.size(), 1u);
  EXPECT_EQ(blob->object.blob_spheres[0].weight.radius, 2.5);
  EXPECT_EQ(blob->object.blob_spheres[0].weight.strength, -4.0);
}

TEST(ItemsBlobSamples, Blob1b) {
  const std::string text = sample_text("blob1b.pov");
  SKIP_IF_MISSING(text);
  const auto result = parse_string(text, "blob1b.pov", ParseOptions{});
  const scene::Implicit* blob = only_blob(result);
  ASSERT_NE(blob, nullptr);
  EXPECT_EQ(blob->object.threshold, 0.5);
  ASSERT_EQ(blob->object.blob_cylinders.size(), 7u);
  ASSERT_EQ(blob->object.blob_spheres.size(), 4u);
  for (const auto& cylinder : blob->object.blob_cylinders) {
    EXPECT_EQ(cylinder.weight.radius, 0.8);
    EXPECT_EQ(cylinder.weight.strength, 1.0);
  }
  EXPECT_EQ(blob->object.blob_spheres[3].weight.radius, 1.5);
  // The blob's own `scale <1, 1, 1.5>` is the object's transform (non-uniform is fine there).
  expect_near(result.scene.objects.back()->transform.point(Vec3(0, 0, 2)), Vec3(0, 0, 3));
}

TEST(ItemsBlobSamples, Blob1c) {
  const std::string text = sample_text("blob1c.pov");
  SKIP_IF_MISSING(text);
  const scene::Implicit* blob = only_blob(parse_string(text, "blob1c.pov", ParseOptions{}));
  ASSERT_NE(blob, nullptr);
  EXPECT_EQ(blob->object.threshold, 0.5);
  ASSERT_EQ(blob->object.blob_spheres.size(), 1u);
  EXPECT_EQ(blob->object.blob_spheres[0].weight.strength, 2.0);
  ASSERT_EQ(blob->object.blob_cylinders.size(), 3u);
  EXPECT_EQ(blob->object.blob_cylinders[2].weight.radius, 0.5);
  expect_near(blob->object.blob_cylinders[2].base, Vec3(0, -2, 0));
}

}  // namespace
}  // namespace convray::sdl
