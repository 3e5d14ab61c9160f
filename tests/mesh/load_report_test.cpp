// What reading does to faces: polygons are triangulated, degenerate triangles dropped, and
// all of it counted.
#include <gtest/gtest.h>

#include "mesh/load.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

double signed_area_z(const TriangleSoup& soup, size_t t) {
  std::array<Vec3, 3> c = soup.corners(t);
  return 0.5 * glm::cross(c[1] - c[0], c[2] - c[0]).z;
}

TEST(LoadReport, CountsDroppedAndTriangulatedFaces) {
  std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 0.5 1.5 0\n"
      "f 1 2 3\n"        // kept
      "f 1 2 5\n"        // collinear: zero area
      "f 1 1 3\n"        // repeated vertex
      "f 1 2 3 4\n"      // quad: two triangles
      "f 1 2 3 6 4\n";   // pentagon: three triangles
  LoadedMesh mesh = load_mesh_from_memory(obj, "faces.obj");
  EXPECT_EQ(mesh.report.faces_read, 5u);
  EXPECT_EQ(mesh.report.polygons_triangulated, 2u);
  EXPECT_EQ(mesh.report.dropped_zero_area, 1u);
  EXPECT_EQ(mesh.report.dropped_repeated_vertex, 1u);
  EXPECT_EQ(mesh.report.triangles_kept, 6u);
  EXPECT_EQ(mesh.soup.size(), 6u);
}

TEST(LoadReport, TriangleFacesKeepTheirCornersInOrder) {
  LoadedMesh mesh = load_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 3 1 2\nf 2 3 1\nf 1 3 2\n", "order.obj");
  ASSERT_EQ(mesh.soup.size(), 3u);
  EXPECT_EQ(mesh.soup.triangles[0], (Triangle{2, 0, 1}));
  EXPECT_EQ(mesh.soup.triangles[1], (Triangle{1, 2, 0}));
  EXPECT_EQ(mesh.soup.triangles[2], (Triangle{0, 2, 1}));
  EXPECT_EQ(mesh.report.polygons_triangulated, 0u);
}

TEST(LoadReport, CoincidentPositionsCountAsZeroArea) {
  // Different indices, same position: no area, but no repeated index either.
  LoadedMesh mesh = load_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n", "twins.obj");
  EXPECT_EQ(mesh.report.dropped_zero_area, 1u);
  EXPECT_EQ(mesh.report.dropped_repeated_vertex, 0u);
}

TEST(LoadReport, ConvexPolygonsBecomeAFanFromTheFirstCorner) {
  LoadedMesh mesh = load_mesh_from_memory("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "quad.obj");
  ASSERT_EQ(mesh.soup.size(), 2u);
  EXPECT_EQ(mesh.soup.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(mesh.soup.triangles[1], (Triangle{0, 2, 3}));
}

TEST(LoadReport, ConcavePolygonsAreEarClipped) {
  // An L-shaped hexagon whose fan from corner 0 would leave the L; area 3.
  std::string obj = "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nf 3 4 5 6 1 2\n";
  LoadedMesh mesh = load_mesh_from_memory(obj, "ell.obj");
  ASSERT_EQ(mesh.soup.size(), 4u);
  double area = 0.0;
  for (size_t t = 0; t < mesh.soup.size(); ++t) {
    EXPECT_GT(signed_area_z(mesh.soup, t), 0.0) << "triangle " << t << " is flipped or flat";
    area += signed_area_z(mesh.soup, t);
  }
  EXPECT_DOUBLE_EQ(area, 3.0);
}

TEST(LoadReport, PlyAndOffPolygonsAreTriangulatedTheSameWay) {
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  std::string off = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  for (const LoadedMesh& mesh : {load_mesh_from_memory(ply, "quad.ply"), load_mesh_from_memory(off, "quad.off")}) {
    EXPECT_EQ(mesh.report.polygons_triangulated, 1u);
    EXPECT_EQ(mesh.soup.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
  }
}

TEST(LoadReport, ObjIgnoresWhatItDoesNotRender) {
  std::string obj =
      "# comment\nmtllib missing.mtl\no thing\ng part\nv 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0\n"
      "vt 0 0\nvn 0 0 1\nusemtl red\ns 1\nl 1 2\nf 1/1/1 2/1/1 3//1\r\nf -3 -2 -1\n";
  LoadedMesh mesh = load_mesh_from_memory(obj, "rich.obj");
  EXPECT_EQ(mesh.soup.size(), 2u);
  EXPECT_EQ(mesh.soup.triangles[1], (Triangle{0, 1, 2}));
}

}  // namespace
}  // namespace convray::mesh
