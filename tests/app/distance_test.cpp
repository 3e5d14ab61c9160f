// `convray distance A B`, run as the user runs it: the built binary, through a shell.
#include <string>

#include "app/cli.hpp"
#include "mesh/procedural.hpp"
#include "mesh/write.hpp"

namespace convray {
namespace {

class DistanceCommand : public testing::CliTest {};

bool has_line(const std::string& output, const std::string& line) {
  return output.find(line + "\n") != std::string::npos;
}

// flat_grid(1, 4) spans [-1, 1]^2 at z = 0; the copy at z = 0.5 is 0.5 away everywhere, and
// the box around both is 2 x 2 x 0.5, diagonal sqrt(8.25) = 2.87228, so 0.5 is 0.174078 of it.
TEST_F(DistanceCommand, SheetAndTheSameSheetShifted) {
  mesh::TriangleSoup sheet = mesh::flat_grid(1.0, 4);
  mesh::save_mesh(sheet, file("a.obj"));
  for (Vec3& p : sheet.vertices) p.z += 0.5;
  mesh::save_mesh(sheet, file("b.ply"));
  testing::CliRun run =
      run_convray("distance '" + file("a.obj") + "' '" + file("b.ply") + "' --samples 100");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_TRUE(has_line(run.out, "A: " + file("a.obj") + " (32 triangles)")) << run.out;
  EXPECT_TRUE(has_line(run.out, "diagonal: 2.87228 (of the box around both)")) << run.out;
  EXPECT_TRUE(has_line(run.out, "A -> B max: 0.5 (0.174078 of the diagonal)")) << run.out;
  EXPECT_TRUE(has_line(run.out, "B -> A mean: 0.5 (0.174078 of the diagonal)")) << run.out;
  EXPECT_TRUE(has_line(run.out, "Hausdorff: 0.5 (0.174078 of the diagonal)")) << run.out;
  EXPECT_TRUE(
      has_line(run.out, "mean: 0.5 (0.174078 of the diagonal) (of the two directions' means)"))
      << run.out;
  EXPECT_EQ(run.err, "");
}

// A small sheet on a large one: 0 one way; the large one's corner is sqrt 2 = 1.41421 from
// the small one's the other way.
TEST_F(DistanceCommand, OneSidedDistancesDiffer) {
  mesh::save_mesh(mesh::flat_grid(1.0, 2), file("small.obj"));
  mesh::save_mesh(mesh::flat_grid(2.0, 2), file("large.obj"));
  testing::CliRun run =
      run_convray("distance '" + file("small.obj") + "' '" + file("large.obj") + "'");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_TRUE(has_line(run.out, "A -> B max: 0 (0 of the diagonal)")) << run.out;
  EXPECT_NE(run.out.find("B -> A max: 1.41421 ("), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("Hausdorff: 1.41421 ("), std::string::npos) << run.out;
}

TEST_F(DistanceCommand, MissingFileExitsWithTwoAndSaysWhich) {
  mesh::save_mesh(mesh::flat_grid(1.0, 2), file("a.obj"));
  testing::CliRun run =
      run_convray("distance '" + file("a.obj") + "' '" + file("nothing.obj") + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(file("nothing.obj")), std::string::npos) << run.err;
  EXPECT_EQ(run.out, "");
}

TEST_F(DistanceCommand, BadArgumentsExitWithTwo) {
  mesh::save_mesh(mesh::flat_grid(1.0, 2), file("a.obj"));
  testing::CliRun one = run_convray("distance '" + file("a.obj") + "'");
  EXPECT_EQ(one.exit_code, 2);
  EXPECT_NE(one.err.find("B is required"), std::string::npos) << one.err;
  testing::CliRun zero =
      run_convray("distance '" + file("a.obj") + "' '" + file("a.obj") + "' --samples 0");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("--samples"), std::string::npos) << zero.err;
}

}  // namespace
}  // namespace convray
