// `convray info MESH`, run as the user runs it: the built binary, through a shell.
#include <string>

#include "app/cli.hpp"

#include "mesh/procedural.hpp"
#include "mesh/write.hpp"

namespace convray {
namespace {

class InfoCommand : public testing::CliTest {
 protected:
  // Standard output and error together: the report, or the message.
  testing::CliRun run(const std::string& arguments) const { return run_convray(arguments); }
};

bool has_line(const std::string& output, const std::string& line) {
  return output.find(line + "\n") != std::string::npos;
}

TEST_F(InfoCommand, ReportsAClosedSphere) {
  std::string path = file("sphere.ply");
  mesh::save_mesh(mesh::icosphere(Vec3(0.0), 2.0, 2), path);
  testing::CliRun run = this->run("info '" + path + "'");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_TRUE(has_line(run.all(), "file: " + path)) << run.all();
  EXPECT_TRUE(has_line(run.all(), "format: PLY binary little-endian")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "triangles: 320")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "vertices: 162 (distinct positions)")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "dropped faces: 0 (zero-area: 0, repeated-vertex: 0)")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "boundary edges: 0")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "non-manifold edges: 0")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "connected components: 1")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "bounding box min: -2 -2 -2")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "size: 4 4 4")) << run.all();
  EXPECT_NE(run.all().find("radius advice: start with R = 0.4 (the smaller of the mean edge length, "), std::string::npos) << run.all();
}

TEST_F(InfoCommand, ReportsTheDefectsOfTheExampleSoup) {
  testing::CliRun run = this->run(std::string("info '") + CONVRAY_SOURCE_DIR + "/scenes/models/soup.obj'");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_TRUE(has_line(run.all(), "triangles: 319")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "faces read: 321")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "dropped faces: 2 (zero-area: 1, repeated-vertex: 1)")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "boundary edges: 7")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "non-manifold edges: 4")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "inconsistently oriented edges: 3")) << run.all();
}

// Face 2 pierces face 1, face 4 repeats face 3, and face 5 touches face 1 with one corner (or,
// in the second file, stops 1e-12 short of it).
std::string crossing_faces_obj(const std::string& touching_height) {
  return "v 0 0 0\nv 2 0 0\nv 0 2 0\n"
         "v 0.5 0.5 -1\nv 0.5 0.5 1\nv 1 0.2 1\n"
         "v 5 5 5\nv 6 5 5\nv 5 6 5\n"
         "v 1 0.5 " + touching_height + "\nv 2 1.5 3\nv 1 1.5 3\n"
         "f 1 2 3\nf 4 5 6\nf 7 8 9\nf 7 8 9\nf 10 11 12\n";
}

TEST_F(InfoCommand, SelfIntersectionsAreCountedExactlyAndListed) {
  const std::string touching = file("touching.obj"), apart = file("apart.obj");
  std::ofstream(touching) << crossing_faces_obj("0");
  std::ofstream(apart) << crossing_faces_obj("1e-12");
  testing::CliRun run = this->run("info --self-intersections '" + touching + "'");
  EXPECT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.all().find("self-intersecting face pairs: 3 ("), std::string::npos) << run.all();
  EXPECT_TRUE(has_line(run.all(), "  faces 1 and 2 intersect")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "  faces 1 and 5 intersect")) << run.all();
  EXPECT_TRUE(has_line(run.all(), "  faces 3 and 4 intersect")) << run.all();
  run = this->run("info --self-intersections '" + apart + "'");
  EXPECT_NE(run.all().find("self-intersecting face pairs: 2 ("), std::string::npos) << run.all();
  EXPECT_FALSE(has_line(run.all(), "  faces 1 and 5 intersect")) << run.all();
  // Without the flag, nothing is said about it.
  run = this->run("info '" + touching + "'");
  EXPECT_EQ(run.all().find("self-intersecting"), std::string::npos) << run.all();
}

TEST_F(InfoCommand, AClosedSphereHasNoSelfIntersectionsAndTheExampleSoupOneRepeatedFace) {
  std::string path = file("sphere.ply");
  mesh::save_mesh(mesh::icosphere(Vec3(0.0), 2.0, 3), path);
  testing::CliRun run = this->run("info --self-intersections '" + path + "'");
  EXPECT_NE(run.all().find("self-intersecting face pairs: 0 ("), std::string::npos) << run.all();
  // scenes/models/soup.obj repeats one face (mesh::defective_soup); its other defects (a hole,
  // a flipped face, a sliver, a fin) make no crossing.
  run = this->run(std::string("info --self-intersections '") + CONVRAY_SOURCE_DIR +
                  "/scenes/models/soup.obj'");
  EXPECT_NE(run.all().find("self-intersecting face pairs: 1 ("), std::string::npos) << run.all();
}

TEST_F(InfoCommand, BadFileExitsWithTwoAndSaysWhy) {
  std::string path = file("bad.off");
  std::ofstream(path) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n";
  testing::CliRun run = this->run("info '" + path + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.all(), path + ":6: face refers to vertex 5, but the file has 3 vertices (face 0)\n");
}

TEST_F(InfoCommand, UnknownFormatExitsWithTwo) {
  testing::CliRun run = this->run("info '" + file("model.3ds") + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.all().find("unknown mesh format '.3ds'"), std::string::npos) << run.all();
}

}  // namespace
}  // namespace convray
