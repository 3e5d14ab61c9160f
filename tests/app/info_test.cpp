// `convray info MESH`, run as the user runs it: the built binary, through a shell.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "mesh/procedural.hpp"
#include "mesh/write.hpp"

namespace convray {
namespace {

struct CommandRun {
  std::string output;  // stdout and stderr together
  int exit_code = -1;
};

CommandRun run_convray(const std::string& arguments) {
  CommandRun run;
  std::string command = std::string("'") + CONVRAY_BINARY + "' " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.output.append(buffer, n);
  int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

class InfoCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() / ("convray-info-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string file(const std::string& name) const { return (directory_ / name).string(); }

 private:
  std::filesystem::path directory_;
};

bool has_line(const std::string& output, const std::string& line) {
  return output.find(line + "\n") != std::string::npos;
}

TEST_F(InfoCommand, ReportsAClosedSphere) {
  std::string path = file("sphere.ply");
  mesh::save_mesh(mesh::icosphere(Vec3(0.0), 2.0, 2), path);
  CommandRun run = run_convray("info '" + path + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(has_line(run.output, "file: " + path)) << run.output;
  EXPECT_TRUE(has_line(run.output, "format: PLY binary little-endian")) << run.output;
  EXPECT_TRUE(has_line(run.output, "triangles: 320")) << run.output;
  EXPECT_TRUE(has_line(run.output, "vertices: 162 (distinct positions)")) << run.output;
  EXPECT_TRUE(has_line(run.output, "dropped faces: 0 (zero-area: 0, repeated-vertex: 0)")) << run.output;
  EXPECT_TRUE(has_line(run.output, "boundary edges: 0")) << run.output;
  EXPECT_TRUE(has_line(run.output, "non-manifold edges: 0")) << run.output;
  EXPECT_TRUE(has_line(run.output, "connected components: 1")) << run.output;
  EXPECT_TRUE(has_line(run.output, "bounding box min: -2 -2 -2")) << run.output;
  EXPECT_TRUE(has_line(run.output, "size: 4 4 4")) << run.output;
  EXPECT_NE(run.output.find("radius advice: start with R = 0.4 (the smaller of the mean edge length, "), std::string::npos) << run.output;
}

TEST_F(InfoCommand, ReportsTheDefectsOfTheExampleSoup) {
  CommandRun run = run_convray(std::string("info '") + CONVRAY_SOURCE_DIR + "/scenes/models/soup.obj'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(has_line(run.output, "triangles: 319")) << run.output;
  EXPECT_TRUE(has_line(run.output, "faces read: 321")) << run.output;
  EXPECT_TRUE(has_line(run.output, "dropped faces: 2 (zero-area: 1, repeated-vertex: 1)")) << run.output;
  EXPECT_TRUE(has_line(run.output, "boundary edges: 7")) << run.output;
  EXPECT_TRUE(has_line(run.output, "non-manifold edges: 4")) << run.output;
  EXPECT_TRUE(has_line(run.output, "inconsistently oriented edges: 3")) << run.output;
}

TEST_F(InfoCommand, BadFileExitsWithTwoAndSaysWhy) {
  std::string path = file("bad.off");
  std::ofstream(path) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n";
  CommandRun run = run_convray("info '" + path + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.output, path + ":6: face refers to vertex 5, but the file has 3 vertices (face 0)\n");
}

TEST_F(InfoCommand, UnknownFormatExitsWithTwo) {
  CommandRun run = run_convray("info '" + file("model.3ds") + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("unknown mesh format '.3ds'"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace convray
