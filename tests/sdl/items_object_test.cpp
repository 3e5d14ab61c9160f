// Object modifiers: transforms in POV-Ray's order and convention, textures that move with
// the transforms given after them, CSG, `object { ID }` copies, clipped_by/bounded_by, flags.
#include <glm/gtc/constants.hpp>

#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;

TEST(ItemsObject, RotateNinetyAboutYTakesXToMinusZ) {
  const auto object = only_object(parse("sphere { 0, 1 rotate 90*y }"));
  expect_near(object->transform.point(Vec3(1, 0, 0)), Vec3(0, 0, -1));
}

TEST(ItemsObject, TransformsApplyInTheOrderWritten) {
  const auto object = only_object(parse("sphere { 0, 1 scale 2 translate <1, 0, 0> }"));
  expect_near(object->transform.point(Vec3(1, 0, 0)), Vec3(3, 0, 0));
  const auto other = only_object(parse("sphere { 0, 1 translate <1, 0, 0> scale 2 }"));
  expect_near(other->transform.point(Vec3(1, 0, 0)), Vec3(4, 0, 0));
}

TEST(ItemsObject, MatrixAndTransformBlock) {
  // Row vectors: x -> <0, 1, 0>, y -> <-1, 0, 0>, z -> z, then the translation <1, 2, 3>.
  const auto object = only_object(parse("sphere { 0, 1 matrix < 0,1,0, -1,0,0, 0,0,1, 1,2,3 > }"));
  expect_near(object->transform.point(Vec3(1, 0, 0)), Vec3(1, 3, 3));
  const auto declared =
      only_object(parse("#declare T = transform { scale 2 translate x }\n"
                        "sphere { 0, 1 transform T transform { T inverse } }"));
  expect_near(declared->transform.point(Vec3(1, 2, 3)), Vec3(1, 2, 3));
}

TEST(ItemsObject, MatrixWhoseLastValueIsAnExpression) {
  // screen.inc ends a matrix with `CamL.z >`: the '>' closes the matrix.
  const auto object = only_object(parse(
      "#declare V = <1, 2, 3>;\nsphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, V.x, V.y, V.z\n> }"));
  expect_near(object->transform.point(Vec3(0.0)), Vec3(1, 2, 3));
}

TEST(ItemsObject, ScaleByZeroIsChangedToOneWithAWarning) {
  const auto result = parse("sphere { 0, 1 scale <2, 0, 1> }");
  expect_near(only_object(result)->transform.point(Vec3(1, 1, 1)), Vec3(2, 1, 1));
  EXPECT_TRUE(has_warning(result, "scale by 0 along y changed to 1"));
}

TEST(ItemsObject, BoundedPolynomialWarnsThatPovRayCutsItThere) {
  // POV-Ray 3.7 cuts a quartic (poly, cubic, quadric) by its bound, a sphere not.
  const auto quartic = parse(
      "quartic { <1,0,0,0,2,0,0,2,0,-10, 0,0,0,0,0,0,0,0,0,0, 1,0,0,2,0,6,0,0,0,0, 1,0,-6,0,9>\n"
      "  bounded_by { sphere { 0, 1.6 } } }");
  EXPECT_TRUE(has_warning(quartic, "POV-Ray also cuts away parts of the surface outside"));
  const auto sphere = parse("sphere { 0, 2 bounded_by { sphere { 0, 1.6 } } }");
  EXPECT_FALSE(has_warning(sphere, "cuts away"));
}

TEST(ItemsObject, SingularMatrixFails) {
  EXPECT_TRUE(fails_with("sphere { 0, 1 matrix <1,0,0, 1,0,0, 0,0,1, 0,0,0> }", 1, 15,
                         "matrix is singular"));
}

TEST(ItemsObject, TextureGivenBeforeATransformMovesWithTheObject) {
  const auto moved = only_object(parse("sphere { 0, 1 pigment { checker } translate <1,2,3> }"));
  expect_near(moved->texture->pigment.space.transform.point(Vec3(0.0)), Vec3(1, 2, 3));
  expect_near(moved->texture->normal.space.transform.point(Vec3(0.0)), Vec3(1, 2, 3));
  const auto fixed = only_object(parse("sphere { 0, 1 translate <1,2,3> pigment { checker } }"));
  EXPECT_TRUE(fixed->texture->pigment.space.transform.is_identity());
}

TEST(ItemsObject, CsgChildrenInOrderAndTheirTexturesMoveWithTheParent) {
  const auto object = only_object(parse(R"(
    difference {
      box { -1, 1 pigment { checker } }
      sphere { 0, 1.2 }
      translate <0, 5, 0>
    })"));
  const auto& csg = shape_of<scene::Csg>(object);
  EXPECT_EQ(csg.operation, scene::CsgOperation::difference);
  ASSERT_EQ(csg.children.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<scene::Box>(csg.children[0]->shape));
  EXPECT_TRUE(std::holds_alternative<scene::Sphere>(csg.children[1]->shape));
  // The child stays in the parent's space; its texture (world space) moved with the parent.
  EXPECT_TRUE(csg.children[0]->transform.is_identity());
  expect_near(csg.children[0]->texture->pigment.space.transform.point(Vec3(0.0)), Vec3(0, 5, 0));
  EXPECT_EQ(csg.children[1]->texture, nullptr);
}

TEST(ItemsObject, AllFourCsgOperations) {
  const char* words[] = {"union", "intersection", "difference", "merge"};
  const scene::CsgOperation operations[] = {
      scene::CsgOperation::union_, scene::CsgOperation::intersection,
      scene::CsgOperation::difference, scene::CsgOperation::merge};
  for (int k = 0; k < 4; ++k) {
    const auto object =
        only_object(parse(std::string(words[k]) + " { sphere { 0, 1 } sphere { x, 1 } }"));
    EXPECT_EQ(shape_of<scene::Csg>(object).operation, operations[k]) << words[k];
  }
}

TEST(ItemsObject, MisspelledChildInCsg) {
  EXPECT_TRUE(fails_with("union { sphere { 0, 1 } sphre { x, 1 } }", 1, 25,
                         "unexpected 'sphre' in union (did you mean 'sphere'?)"));
}

TEST(ItemsObject, CsgChildrenAfterModifiersFail) {
  EXPECT_TRUE(fails_with("union { sphere { 0, 1 } pigment { rgb 1 } sphere { x, 1 } }", 1, 43,
                         "the union's objects must come before the object's modifiers "
                         "(first: 'pigment' at test.pov:1:25)"));
}

TEST(ItemsObject, DeclaredObjectIsSharedOrCopied) {
  const auto result = parse(R"(
    #declare Ball = sphere { 0, 1 pigment { checker } }
    object { Ball }
    object { Ball translate x })");
  ASSERT_EQ(result.scene.objects.size(), 2u);
  const scene::ObjectPtr& declared = *result.globals.at("Ball").get<scene::ObjectPtr>();
  EXPECT_EQ(result.scene.objects[0], declared);  // no modifiers: the same record
  const auto& copy = result.scene.objects[1];
  EXPECT_NE(copy, declared);
  EXPECT_TRUE(declared->transform.is_identity());
  expect_near(copy->transform.point(Vec3(0.0)), Vec3(1, 0, 0));
  expect_near(copy->texture->pigment.space.transform.point(Vec3(0.0)), Vec3(1, 0, 0));
  EXPECT_EQ(copy->loc.line, 4);
}

TEST(ItemsObject, ObjectOfALightSourceAddsTheLightAtTheTopLevel) {
  const auto result = parse("#declare L = light_source { 0, 1 }\nobject { L translate y }");
  ASSERT_EQ(result.scene.lights.size(), 1u);
  expect_near(result.scene.lights[0].position, Vec3(0, 1, 0));
  EXPECT_TRUE(result.scene.objects.empty());
  EXPECT_TRUE(fails_with("#declare L = light_source { 0, 1 }\nunion { object { L } }", 2, 18,
                         "'L' is a light_source"));
}

TEST(ItemsObject, InteriorTextureIsKeptBesideTheTexture) {
  const auto result =
      parse("box { -1, 1 pigment { rgb 1 } interior_texture { pigment { rgb <1, 0, 0> } } }");
  // interior_texture is not the texture: each keeps its own pigment.
  EXPECT_EQ(only_object(result)->texture->pigment.color.rgb, Vec3(1.0));
  ASSERT_TRUE(only_object(result)->interior_texture);
  EXPECT_EQ(only_object(result)->interior_texture->pigment.color.rgb, Vec3(1, 0, 0));
  EXPECT_FALSE(has_warning(result, "interior_texture"));
}

TEST(ItemsObject, DefaultWithoutHashSetsTheDefaults) {
  const auto result =
      parse("default { finish { ambient 0.5 } }\nsphere { 0, 1 pigment { rgb 1 } }");
  expect_near(only_object(result)->texture->finish.ambient, Vec3(0.5));
}

TEST(ItemsObject, PigmentOnAnObjectModifiesItsTextureFromTheDefaults) {
  const auto result = parse(R"(
    #default { finish { ambient 0.3 } }
    sphere { 0, 1 pigment { rgb <1, 0, 0> } finish { phong 1 } })");
  const auto& texture = *only_object(result)->texture;
  expect_near(texture.pigment.color.rgb, Vec3(1, 0, 0));
  expect_near(texture.finish.ambient, Vec3(0.3));
  EXPECT_EQ(texture.finish.phong, 1.0);
}

TEST(ItemsObject, SecondTextureLiesOverTheFirst) {
  // POV-Ray's layered textures: the later one on top, the earlier seen through it.
  const auto result = parse(
      "sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.7> } } }");
  const scene::Texture& top = *only_object(result)->texture;
  expect_near(top.pigment.color.rgb, Vec3(1, 0, 0));
  ASSERT_TRUE(top.below);
  expect_near(top.below->pigment.color.rgb, Vec3(1.0));
  EXPECT_FALSE(top.below->below);
}

TEST(ItemsObject, LayeredTextureDeclarationKeepsEveryLayer) {
  const auto result = parse(R"(
    #declare Layered = texture { pigment { rgb <0, 1, 0> } }
                       texture { pigment { bozo color_map { [0 rgbt <1, 0, 0, 1>] [1 rgb 0] } } }
                       texture { pigment { rgbt <0, 0, 1, 0.5> } }
    #declare Next = texture { Layered }
    sphere { 0, 1 texture { Next } translate x })");
  const scene::Texture& top = *only_object(result)->texture;
  expect_near(top.pigment.color.rgb, Vec3(0, 0, 1));
  ASSERT_TRUE(top.below && top.below->below);
  EXPECT_EQ(top.below->pigment.space.pattern, scene::Pattern::bozo);
  expect_near(top.below->below->pigment.color.rgb, Vec3(0, 1, 0));
  // The object's translation moves every layer's pattern.
  expect_near(top.below->pigment.space.transform.inverse_point(Vec3(1, 0, 0)), Vec3(0.0));
}

TEST(ItemsObject, ATopLevelTextureMustFollowADeclaredOne) {
  EXPECT_TRUE(fails_with("sphere { 0, 1 }\ntexture { pigment { rgb 1 } }", 2, 1,
                         "must follow a declared texture"));
}

TEST(ItemsObject, DeclarationsFollowingEachOtherWithoutSemicolons) {
  const auto result = parse(R"(
    #declare Clay = texture { pigment { rgb <1, 0.5, 0> } }
    #declare Ball = sphere { 0, 1 texture { Clay } }
    object { Ball })");
  expect_near(only_object(result)->texture->pigment.color.rgb, Vec3(1, 0.5, 0));
}

TEST(ItemsObject, DeclaredMaterialKeepsItsTexture) {
  const auto result = parse(R"(
    #declare M = material { texture { pigment { rgb <0, 0, 1> } } interior { ior 1.5 } }
    sphere { 0, 1 material { M } })");
  expect_near(only_object(result)->texture->pigment.color.rgb, Vec3(0, 0, 1));
  EXPECT_TRUE(has_warning(result, "its interior is dropped"));
}

TEST(ItemsObject, UnsupportedObjectsFailButMayBeDeclared) {
  EXPECT_TRUE(fails_with("union { sphere { 0, 1 } ovus { } }", 1, 25,
                         "'ovus' objects are not supported yet"));
  // text objects are drawn now: a missing font is the error, at its name.
  EXPECT_TRUE(fails_with("text { ttf \"no-such-font.ttf\" \"A\" 1, 0 }", 1, 12,
                         "file not found: 'no-such-font.ttf'"));
  // Include files declare such objects that most scenes never use: declaring one warns.
  const auto result = parse("#declare L = ovus { 1, 0.5 }");
  EXPECT_TRUE(has_warning(result, "'ovus' objects are not supported yet"));
}

TEST(ItemsObject, FlagsAndInterior) {
  const auto object = only_object(
      parse("sphere { 0, 1 inverse no_shadow hollow interior { ior 1.5 } double_illuminate }"));
  EXPECT_TRUE(object->inverse);
  EXPECT_TRUE(object->no_shadow);
  EXPECT_TRUE(object->hollow);
  ASSERT_TRUE(object->interior.has_value());
  EXPECT_EQ(object->interior->ior, 1.5);
  EXPECT_FALSE(only_object(parse("sphere { 0, 1 hollow off }"))->hollow);
  EXPECT_TRUE(object->double_illuminate);
  const auto hidden = parse("sphere { 0, 1 no_image no_reflection }");
  EXPECT_TRUE(only_object(hidden)->no_image);
  EXPECT_TRUE(only_object(hidden)->no_reflection);
  EXPECT_FALSE(has_warning(hidden, "ignored"));
  EXPECT_TRUE(has_warning(parse("sphere { 0, 1 no_radiosity }"), "'no_radiosity' is ignored"));
}

TEST(ItemsObject, SplitUnionIsOnUnlessTurnedOff) {
  const char* members = "sphere { 0, 1 } sphere { x, 1 }";
  EXPECT_TRUE(only_object(parse(std::string("union { ") + members + " }"))->split_union);
  EXPECT_TRUE(only_object(parse(std::string("union { ") + members + " split_union }"))->split_union);
  const auto off = parse(std::string("union { ") + members + " split_union off }");
  EXPECT_FALSE(only_object(off)->split_union);
  EXPECT_FALSE(has_warning(off, "split_union"));  // honoured, not ignored
}

TEST(ItemsObject, MaterialSetsTextureAndInterior) {
  const auto object = only_object(
      parse("sphere { 0, 1 material { texture { pigment { rgb y } } interior { ior 1.33 } } }"));
  expect_near(object->texture->pigment.color.rgb, Vec3(0, 1, 0));
  EXPECT_EQ(object->interior->ior, 1.33);
}

TEST(ItemsObject, ClippedByIsStoredInTheObjectsOwnSpace) {
  const auto object =
      only_object(parse("sphere { 0, 1 translate <0, 2, 0> clipped_by { plane { y, 0 } } "
                        "bounded_by { box { -3, 3 } } }"));
  ASSERT_EQ(object->clipped_by.size(), 1u);
  // The plane was written in the space the sphere had been moved to; composed with the
  // object's transform it must land back where it was written.
  const scene::Transform world = object->clipped_by[0]->transform.then(object->transform);
  expect_near(world.point(Vec3(0.0)), Vec3(0.0));
  ASSERT_NE(object->bounded_by, nullptr);
  EXPECT_TRUE(std::holds_alternative<scene::Box>(object->bounded_by->shape));
}

TEST(ItemsObject, ClippedByBoundedByAndTheReverse) {
  const auto object =
      only_object(parse("sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } }"));
  ASSERT_EQ(object->clipped_by.size(), 1u);
  EXPECT_EQ(object->clipped_by[0], object->bounded_by);
  const auto other =
      only_object(parse("sphere { 0, 1 clipped_by { box { -1, 1 } } bounded_by { clipped_by } }"));
  EXPECT_EQ(other->bounded_by, other->clipped_by[0]);
}

TEST(ItemsObject, LightsInsideCsgArePlacedWithIt) {
  // Each placement of the object places its lights: nested CSGs and the object { }'s own
  // transforms included.
  const auto result = parse(R"(
    #declare Lamp = union { light_source { <1, 0, 0>, 1 } sphere { 0, 1 } translate 2 * y }
    object { Lamp translate 3 * z }
    union { object { Lamp } light_source { <0, 0, 1>, 1 spotlight point_at <0, 0, 2> }
      rotate 90 * y })");
  ASSERT_EQ(result.scene.lights.size(), 3u);
  expect_near(result.scene.lights[0].position, Vec3(1, 2, 3));
  expect_near(result.scene.lights[1].position, Vec3(1, 0, 0));   // spotlight first in the union
  expect_near(result.scene.lights[1].point_at, Vec3(2, 0, 0));
  expect_near(result.scene.lights[2].position, Vec3(0, 2, -1));  // <1, 2, 0> turned about y
  EXPECT_EQ(result.scene.objects.size(), 2u);
  EXPECT_TRUE(fails_with("union { sphere { 0, 1 } sphere { 1, 1 } scale 2 light_source { 0, 1 } }",
                         1, 49, "light sources must come before"));
}

TEST(ItemsObject, ArrayElementsNameItems) {
  const auto result = parse(R"(
    #declare Things = array[2] { sphere { 0, 1 }, box { -1, 1 } }
    #declare Textures = array[2] { texture { pigment { rgb x } }, texture { pigment { rgb y } } }
    #declare Colors = array[2] { rgb <0, 0, 1>, rgb <1, 1, 0> }
    object { Things[1] texture { Textures[1] } }
    sphere { 0, 1 pigment { Colors[0] } })");
  ASSERT_EQ(result.scene.objects.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<scene::Box>(result.scene.objects[0]->shape));
  expect_near(result.scene.objects[0]->texture->pigment.color.rgb, Vec3(0, 1, 0));
  expect_near(result.scene.objects[1]->texture->pigment.color.rgb, Vec3(0, 0, 1));
  EXPECT_TRUE(fails_with("#declare A = array[1] { 1 }\nsphere { 0, 1 texture { A[0] } }", 2, 25,
                         "expected a texture, found a float"));
}

}  // namespace
}  // namespace convray::sdl
