// scenes/models/soup.obj, the default example mesh, is defective_soup() with every defect,
// written by our OBJ writer. These tests keep the shipped file and the generator in step;
// after changing either, regenerate the file with
//     CONVRAY_REGENERATE_MODELS=1 ./test_mesh --gtest_filter='ExampleModel.*'
#include <gtest/gtest.h>

#include <cstdlib>

#include "fixtures/defective_soups.hpp"
#include "mesh/load.hpp"
#include "mesh/stats.hpp"
#include "mesh/write.hpp"
#include "mesh_test_support.hpp"

namespace convray::mesh {
namespace {

const std::string kShipped = std::string(CONVRAY_SOURCE_DIR) + "/scenes/models/soup.obj";

SoupDefects every_defect() {
  SoupDefects defects;
  defects.zero_area = true;
  defects.repeated_vertex = true;
  return defects;
}

TEST(ExampleModel, MatchesItsGenerator) {
  TriangleSoup generated = defective_soup(every_defect());
  if (std::getenv("CONVRAY_REGENERATE_MODELS")) save_mesh(generated, kShipped);
  // The last bits of the positions depend on the compiler (with -march=native it fuses
  // multiply-adds), so positions are compared with a tolerance, the rest exactly.
  LoadedMesh shipped = load_mesh(kShipped);
  ASSERT_EQ(shipped.soup.vertices.size(), generated.vertices.size()) << kShipped << " is out of date";
  for (size_t v = 0; v < generated.vertices.size(); ++v) {
    EXPECT_NEAR(glm::distance(shipped.soup.vertices[v], generated.vertices[v]), 0.0, 1e-12) << "vertex " << v;
  }
  std::vector<Triangle> proper;  // the loader drops the zero-area and repeated-vertex ones
  for (size_t t = 0; t < generated.size(); ++t) {
    std::array<Vec3, 3> c = generated.corners(t);
    if (glm::cross(c[1] - c[0], c[2] - c[0]) != Vec3(0.0)) proper.push_back(generated.triangles[t]);
  }
  EXPECT_EQ(shipped.soup.triangles, proper) << kShipped << " is out of date: regenerate it (see above)";
  EXPECT_LT(testing::read_bytes(kShipped).size(), 50u * 1024);
}

TEST(ExampleModel, LoadsWithItsDefectsReported) {
  LoadedMesh mesh = load_mesh(kShipped);
  EXPECT_EQ(mesh.report.faces_read, 321u);
  EXPECT_EQ(mesh.report.dropped_zero_area, 1u);
  EXPECT_EQ(mesh.report.dropped_repeated_vertex, 1u);
  EXPECT_EQ(mesh.report.triangles_kept, 319u);
  MeshStats stats = compute_stats(mesh.soup);
  EXPECT_EQ(stats.boundary_edges, 7u);
  EXPECT_EQ(stats.non_manifold_edges, 4u);
  EXPECT_EQ(stats.inconsistent_edges, 3u);
  EXPECT_EQ(stats.connected_components, 1u);
}

}  // namespace
}  // namespace convray::mesh
