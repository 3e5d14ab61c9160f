// mesh and mesh2: faces, normals, per-face textures, inside_vector, and the errors of
// inconsistent lists.
#include "items_test_support.hpp"

namespace convray::sdl {
namespace {

using namespace testing;

TEST(ItemsMesh, TrianglesWithTexturesAndInsideVector) {
  const auto object = only_object(parse(R"(
    mesh {
      triangle { <0,0,0>, <1,0,0>, <0,1,0> }
      smooth_triangle { <0,0,0>, <0,0,-1>, <1,0,0>, <0,0,-1>, <0,0,1>, <0,1,0>
                        texture { pigment { rgb <1, 0, 0> } } }
      inside_vector <0, 0, 1>
    })"));
  const auto& mesh = shape_of<scene::TriangleMesh>(object);
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.faces[0].texture, -1);
  EXPECT_EQ(mesh.faces[0].normals[0], -1);
  ASSERT_EQ(mesh.textures.size(), 1u);
  EXPECT_EQ(mesh.faces[1].texture, 0);
  expect_near(mesh.textures[0]->pigment.color.rgb, Vec3(1, 0, 0));
  expect_near(mesh.vertices[size_t(mesh.faces[1].vertices[2])], Vec3(0, 0, 1));
  expect_near(mesh.normals[size_t(mesh.faces[1].normals[2])], Vec3(0, 1, 0));
  ASSERT_TRUE(mesh.inside_vector.has_value());
  expect_near(*mesh.inside_vector, Vec3(0, 0, 1));
}

TEST(ItemsMesh, DegenerateTrianglesAreDroppedWithAWarning) {
  const auto result = parse("mesh { triangle { 0, x, y } triangle { 0, x, 2*x } }");
  EXPECT_EQ(shape_of<scene::TriangleMesh>(only_object(result)).faces.size(), 1u);
  EXPECT_TRUE(has_warning(result, "1 degenerate triangle(s)"));
}

TEST(ItemsMesh, FaceTexturesMoveWithTheMesh) {
  const auto object = only_object(
      parse("mesh { triangle { 0, x, y texture { pigment { checker } } } translate <0, 0, 5> }"));
  const auto& mesh = shape_of<scene::TriangleMesh>(object);
  expect_near(mesh.textures[0]->pigment.space.transform.point(Vec3(0.0)), Vec3(0, 0, 5));
}

TEST(ItemsMesh, Mesh2WithNormalsAndTextures) {
  const auto object = only_object(parse(R"(
    mesh2 {
      vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
      normal_vectors { 1, <0,0,-1> }
      texture_list { 2, texture { pigment { rgb 1 } }, texture { pigment { rgb <0,0,1> } } }
      face_indices { 2, <0,1,2>, 0, <0,2,3>, 1 }
      normal_indices { 2, <0,0,0>, <0,0,0> }
      scale 2
    })"));
  const auto& mesh = shape_of<scene::TriangleMesh>(object);
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.faces[1].vertices[2], 3);
  EXPECT_EQ(mesh.faces[1].texture, 1);
  EXPECT_EQ(mesh.faces[0].normals[1], 0);
  expect_near(mesh.textures[1]->pigment.color.rgb, Vec3(0, 0, 1));
  expect_near(object->transform.point(Vec3(1, 1, 0)), Vec3(2, 2, 0));
}

TEST(ItemsMesh, Mesh2NormalsDefaultToTheFaceIndices) {
  const auto object = only_object(parse(R"(
    mesh2 {
      vertex_vectors { 3, 0, x, y }
      normal_vectors { 3, -z, -z, -z }
      face_indices { 1, <2, 1, 0> }
    })"));
  const auto& mesh = shape_of<scene::TriangleMesh>(object);
  EXPECT_EQ(mesh.faces[0].normals[0], 2);
}

TEST(ItemsMesh, Mesh2CountsWithoutACommaBeforeAVector) {
  // objects/mesh2.pov writes `vertex_vectors { 14 <-1, -1, -1>, ...`: a count, then a vector
  // (POV-Ray renders it), not the comparison 14 < -1.
  const auto object = only_object(parse(R"(
    mesh2 {
      vertex_vectors { 3 <-1, 0, 0>, x, y }
      face_indices { 1 <2, 1, 0> }
    })"));
  const auto& mesh = shape_of<scene::TriangleMesh>(object);
  ASSERT_EQ(mesh.vertices.size(), 3u);
  expect_near(mesh.vertices[0], Vec3(-1, 0, 0));
  EXPECT_EQ(mesh.faces[0].vertices[0], 2);
}

TEST(ItemsMesh, Mesh2Errors) {
  EXPECT_TRUE(fails_with("mesh2 {\n vertex_vectors { 3, 0, x }\n face_indices { 1, <0,1,2> } }", 2,
                         2, "vertex_vectors says 3 but lists 2"));
  EXPECT_TRUE(
      fails_with("mesh2 { vertex_vectors { 3, 0, x, y }\n"
                 "face_indices { 2, <0,1,2>, <0,1,3> } }",
                 1, 1, "face 1 refers to vertex 3, but there are 3"));
  EXPECT_TRUE(
      fails_with("mesh2 { vertex_vectors { 3, 0, x, y }\n"
                 "face_indices { 1, <0,1.5,2> } }",
                 2, 19, "indices must be whole numbers"));
  EXPECT_TRUE(
      fails_with("mesh2 { vertex_vectors { 3, 0, x, y } }", 1, 1, "mesh2 needs face_indices"));
  EXPECT_TRUE(
      fails_with("mesh2 { vertex_vectors { 3, 0, x, y }\n"
                 "face_indices { 1, <0,1,2>, 4 } }",
                 1, 1, "refers to texture 4, but texture_list has 0"));
}

TEST(ItemsMesh, EmptyMeshFails) {
  EXPECT_TRUE(fails_with("mesh { }", 1, 1, "mesh has no triangles"));
  EXPECT_TRUE(fails_with("mesh { triangle { 0, x, y } scale 2 triangle { 0, x, z } }", 1, 37,
                         "the mesh's triangles must come before the object's modifiers "
                         "(first: 'scale' at test.pov:1:29)"));
}

}  // namespace
}  // namespace convray::sdl
