// `convray polygonize`, run as a user runs it; `convray info` on its output confirms the mesh is
// closed and 2-manifold, as the issue asks.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/cli.hpp"
#include "mesh/load.hpp"
#include "mesh/procedural.hpp"
#include "mesh/write.hpp"

namespace convray {
namespace {

class PolygonizeCommand : public testing::CliTest {
 protected:
  std::string models() const { return std::string(CONVRAY_SOURCE_DIR) + "/scenes/models/"; }
};

bool has_line(const std::string& output, const std::string& line) {
  return output.find(line + "\n") != std::string::npos;
}

TEST_F(PolygonizeCommand, HoledSheetBecomesAClosedManifoldThatInfoConfirms) {
  for (const std::string name : {"sheet.obj", "sheet.ply", "sheet.stl"}) {
    const std::string out = file(name);
    const testing::CliRun run = run_convray("polygonize '" + models() +
                                            "holed_sheet.obj' --radius 1 --offset 0.7 --cell 0.12 "
                                            "-o '" +
                                            out + "'");
    ASSERT_EQ(run.exit_code, 0) << run.all();
    EXPECT_NE(run.out.find("boundary edges 0, non-manifold edges 0"), std::string::npos) << run.out;
    const testing::CliRun info = run_convray("info '" + out + "'");
    EXPECT_EQ(info.exit_code, 0) << info.all();
    EXPECT_TRUE(has_line(info.out, "boundary edges: 0")) << info.out;
    EXPECT_TRUE(has_line(info.out, "non-manifold edges: 0")) << info.out;
    EXPECT_TRUE(has_line(info.out, "inconsistently oriented edges: 0")) << info.out;
  }
}

TEST_F(PolygonizeCommand, ObjOutputCarriesOneUnitNormalPerVertex) {
  const std::string out = file("sphere.obj");
  mesh::save_mesh(mesh::icosphere(Vec3(0.0), 1.0, 1), file("in.obj"));
  const testing::CliRun run = run_convray(
      "polygonize '" + file("in.obj") + "' --radius 0.5 --offset 0.2 --cell 0.1 -o '" + out + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  std::ifstream in(out);
  size_t vertices = 0, normals = 0, faces = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0) ++vertices;
    if (line.rfind("vn ", 0) == 0) {
      ++normals;
      double x, y, z;
      ASSERT_EQ(std::sscanf(line.c_str(), "vn %lf %lf %lf", &x, &y, &z), 3);
      EXPECT_NEAR(x * x + y * y + z * z, 1.0, 1e-12);
    }
    if (line.rfind("f ", 0) == 0) {
      ++faces;
      EXPECT_NE(line.find("//"), std::string::npos) << line;
    }
  }
  EXPECT_GT(faces, 0u);
  EXPECT_EQ(vertices, normals);
}

TEST_F(PolygonizeCommand, OuterKeepsOneShellOfAClosedInput) {
  mesh::save_mesh(mesh::icosphere(Vec3(0.0), 1.0, 2), file("in.ply"));
  const std::string args =
      "polygonize '" + file("in.ply") + "' --radius 0.3 --offset 0.1 --cell 0.05 ";
  const testing::CliRun both = run_convray(args + "-o '" + file("both.obj") + "'");
  ASSERT_EQ(both.exit_code, 0) << both.all();
  EXPECT_NE(both.out.find("components 2, Euler characteristic 4"), std::string::npos) << both.out;
  const testing::CliRun outer = run_convray(args + "--outer -o '" + file("outer.obj") + "'");
  ASSERT_EQ(outer.exit_code, 0) << outer.all();
  EXPECT_NE(outer.out.find("components 1, Euler characteristic 2"), std::string::npos) << outer.out;
  EXPECT_NE(outer.out.find("kept 1 shell(s)"), std::string::npos) << outer.out;
  // Every kept vertex lies outside the input sphere, near radius 1 + offset.
  const mesh::LoadedMesh kept = mesh::load_mesh(file("outer.obj"));
  for (const Vec3& p : kept.soup.vertices) EXPECT_GT(glm::length(p), 1.0);
}

TEST_F(PolygonizeCommand, SceneObjectComesOutWhereTheScenePlacesIt) {
  std::ofstream(file("blobs.pov")) << "#declare Blobs = convolution {\n  radius 1\n"
                                      "  threshold 0.3\n  point { <0, 0, 0> }\n"
                                      "  translate <5, 0, 0>\n}\n";
  const testing::CliRun run =
      run_convray("polygonize '" + file("blobs.pov") + "' --object Blobs --cell 0.05 -o '" +
                  file("b.obj") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  // A point kernel's level set (1 - d^2)^2 = 0.3 is a sphere of radius sqrt(1 - sqrt(0.3)).
  const double radius = std::sqrt(1.0 - std::sqrt(0.3));
  const mesh::LoadedMesh out = mesh::load_mesh(file("b.obj"));
  ASSERT_FALSE(out.soup.vertices.empty());
  for (const Vec3& p : out.soup.vertices) {
    EXPECT_NEAR(glm::length(p - Vec3(5.0, 0.0, 0.0)), radius, 1e-6);
  }
}

TEST_F(PolygonizeCommand, CauchyPointTruncatedByItsBoxGivesTheBox) {
  // kernel cauchy 1 on a point: 1/(1 + r^2)^2 = 0.05 at r = 1.86, far outside the truncation
  // box (the point grown by 0.5), so F >= T fills the whole box and jumps to 0 at its faces:
  // the surface is the cube of half-size 0.5, closed, every vertex on a face.
  std::ofstream(file("c.pov")) << "#declare C = convolution {\n  kernel cauchy 1\n"
                                  "  radius 0.5\n  threshold 0.05\n  point { <1, 2, 3> }\n}\n";
  const testing::CliRun run = run_convray("polygonize '" + file("c.pov") +
                                          "' --object C --cell 0.1 -o '" + file("c.obj") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("boundary edges 0, non-manifold edges 0"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("at jumps of the field"), std::string::npos) << run.out;
  const mesh::LoadedMesh out = mesh::load_mesh(file("c.obj"));
  ASSERT_FALSE(out.soup.vertices.empty());
  for (const Vec3& p : out.soup.vertices) {
    const Vec3 d = glm::abs(p - Vec3(1.0, 2.0, 3.0));
    EXPECT_NEAR(std::max({d.x, d.y, d.z}), 0.5, 1e-9);
  }
}

TEST_F(PolygonizeCommand, BadInputSaysWhyExitsWithTwoAndWritesNothing) {
  const std::string sheet = "'" + models() + "holed_sheet.obj'";
  std::ofstream(file("blobs.pov")) << "#declare Blobs = convolution { radius 1 point { 0 } }\n"
                                      "#declare Ball = sphere { 0, 1 }\n";
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"'" + file("missing.obj") + "' -o OUT", "missing.obj"},
      {sheet + " --radius 1 --offset 1.5 -o OUT", "--offset must satisfy 0 <= offset < radius"},
      {sheet + " --radius 1 --threshold -1 -o OUT", "--threshold must be > 0"},
      {sheet + " --radius 1 --cell 0.1 --max-error 0.01 -o OUT", "excludes"},
      {sheet + " --radius 1 --cell 0 -o OUT", "must be > 0"},
      {sheet + " --radius 1 -o '" + file("out.obj.gz") + "'", ".gz"},
      {sheet + " --radius 1 -o '" + file("out.xyz") + "'", "xyz"},
      {sheet + " --radius 1 --cell 1e-9 -o OUT", "too small"},
      {"'" + file("blobs.pov") + "' --object Nope -o OUT", "no identifier 'Nope'"},
      {"'" + file("blobs.pov") + "' --object Ball -o OUT", "not a convolution object or blob"},
      {"'" + file("blobs.pov") + "' --object Blobs --radius 2 -o OUT", "are for meshes"},
  };
  for (const auto& c : cases) {
    std::string arguments = c.arguments;
    const size_t out = arguments.find("OUT");
    if (out != std::string::npos) arguments.replace(out, 3, "'" + file("out.obj") + "'");
    const testing::CliRun run = run_convray("polygonize " + arguments);
    EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.all();
    EXPECT_NE(run.err.find(c.message), std::string::npos) << arguments << "\n" << run.err;
    EXPECT_FALSE(std::filesystem::exists(file("out.obj"))) << arguments;
  }
}

// An empty surface is the input's fault (a threshold no point reaches): exit 2, as for any bad
// input (issue 21; it was exit 1, the code for internal errors).
TEST_F(PolygonizeCommand, EmptySurfaceExitsWithTwoAndWritesNothing) {
  std::ofstream(file("blobs.pov")) << "#declare Blobs = convolution { radius 1 point { 0 } }\n";
  const testing::CliRun run =
      run_convray("polygonize '" + file("blobs.pov") + "' --object Blobs --threshold 5 -o '" +
                  file("o.obj") + "'");
  EXPECT_EQ(run.exit_code, 2) << run.all();
  EXPECT_NE(run.err.find("the surface is empty: the field stays below T = 5 everywhere"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(std::filesystem::exists(file("o.obj")));
}

}  // namespace
}  // namespace convray
