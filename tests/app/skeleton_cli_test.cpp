// Files without faces (point clouds, polylines, PLY edges) as skeletons, through the commands
// a user runs: info, quick, field and polygonize. Expected values are worked out by hand.
#include <cmath>
#include <fstream>
#include <string>

#include "app/cli.hpp"
#include "mesh/load.hpp"

namespace convray {
namespace {

class SkeletonCommands : public testing::CliTest {
 protected:
  static std::string corpus(const std::string& name) {
    return std::string("'") + CONVRAY_SOURCE_DIR + "/tests/data/meshes/" + name + "'";
  }
};

bool has_line(const std::string& output, const std::string& line) {
  return output.find(line + "\n") != std::string::npos;
}

TEST_F(SkeletonCommands, InfoReportsAPointCloudAndAdvisesARadiusFromItsSpacing) {
  // Points (k, 0, k^2), k = 0..4: nearest neighbours sqrt 2, sqrt 2, sqrt 10, sqrt 26, sqrt 50,
  // mean 3.63216; twice that against a tenth of the largest size (16).
  const testing::CliRun run = run_convray("info " + corpus("ply_points.ply"));
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_TRUE(has_line(run.out, "triangles: 0")) << run.out;
  EXPECT_TRUE(has_line(run.out, "segments: 0")) << run.out;
  EXPECT_TRUE(has_line(run.out, "points: 5")) << run.out;
  EXPECT_TRUE(has_line(run.out, "point cloud: the file has no faces and no lines, so every vertex is a point"));
  EXPECT_TRUE(has_line(run.out, "mean point spacing: 3.63216 (mean distance from each point to its nearest neighbour)"))
      << run.out;
  EXPECT_NE(run.out.find("radius advice: start with R = 1.6 (the smaller of twice the mean point spacing, 7.26432"),
            std::string::npos) << run.out;
}

TEST_F(SkeletonCommands, InfoReportsSegmentsAndTrianglesTogether) {
  const testing::CliRun run = run_convray("info " + corpus("ply_faces_and_edges.ply"));
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_TRUE(has_line(run.out, "triangles: 2")) << run.out;
  EXPECT_TRUE(has_line(run.out, "segments: 4")) << run.out;
  EXPECT_TRUE(has_line(run.out, "mean segment length: 1")) << run.out;
}

TEST_F(SkeletonCommands, FieldOfAPointCloudIsTheSumOfKernels) {
  // Points at the origin and at (3, 0, 0), R = 1: at (0.5, 0, 0) only the first reaches,
  // (1 - 0.25)^2 = 0.5625, gradient -4 (1 - 0.25) (0.5, 0, 0) / R^2 = (-1.5, 0, 0).
  std::ofstream(file("two.obj")) << "v 0 0 0\nv 3 0 0\n";
  const testing::CliRun run = run_convray("field --mesh '" + file("two.obj") + "' --radius 1", "0.5 0 0\n5 5 5\n");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_EQ(run.out, "0.5625 -1.5 0 0\n0 0 0 0\n");
}

TEST_F(SkeletonCommands, QuickRendersALineSetAndAPointCloud) {
  testing::CliRun run = run_convray("quick " + corpus("ply_edges.ply") + " --size 32x24 -o '" + file("edges.png") + "'");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("(0 triangles, 12 segments, R = 0.1, "), std::string::npos) << run.out;
  run = run_convray("quick " + corpus("obj_points.obj") + " --size 32x24 -o '" + file("points.png") + "'");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("(0 triangles, 6 points, "), std::string::npos) << run.out;
  // The default threshold puts a lone point's surface at R/2: (1 - 1/4)^2.
  EXPECT_NE(run.out.find(", T = 0.5625)"), std::string::npos) << run.out;
}

TEST_F(SkeletonCommands, PolygonizingOnePointGivesASphereOfTheOffset) {
  std::ofstream(file("one.obj")) << "v 1 2 3\n";
  const testing::CliRun run = run_convray("polygonize '" + file("one.obj") + "' --radius 1 --offset 0.4 --cell 0.05 -o '" +
                                          file("ball.obj") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  const mesh::LoadedMesh ball = mesh::load_mesh(file("ball.obj"));
  ASSERT_GT(ball.soup.size(), 100u);
  double worst = 0.0;
  for (const Vec3& v : ball.soup.vertices) worst = std::max(worst, std::abs(glm::length(v - Vec3(1, 2, 3)) - 0.4));
  EXPECT_LT(worst, 1e-5);
}

TEST_F(SkeletonCommands, CommandsThatNeedTrianglesSaySo) {
  const testing::CliRun run =
      run_convray("slice " + corpus("ply_points.ply") + " --radius 1 -o '" + file("slice.png") + "'");
  EXPECT_EQ(run.exit_code, 2) << run.all();
  EXPECT_NE(run.err.find("ply_points.ply: slice needs triangles, but the file has none (0 segments, 5 points)"),
            std::string::npos) << run.err;
}

TEST_F(SkeletonCommands, BrokenFilesExitWithTwoAndTheirMessage) {
  for (const char* name : {"broken_ply_header_mismatch.ply", "broken_ply_truncated.ply", "broken_ply_index.ply",
                           "broken_ply_no_end_header.ply", "broken_obj_two_corners.obj", "broken_obj_index.obj",
                           "broken_obj_vertex.obj", "broken_stl_truncated.stl", "broken_off_dimension.off",
                           "broken_off_index.off"}) {
    const testing::CliRun run = run_convray("info " + corpus(name));
    EXPECT_EQ(run.exit_code, 2) << name << ": " << run.all();
    EXPECT_NE(run.err.find(std::string(name) + ":"), std::string::npos) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
}

}  // namespace
}  // namespace convray
