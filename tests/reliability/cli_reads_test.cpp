// What a scene may read, and what reaches the terminal (issue 20): POV-Ray's I/O
// restrictions for includes and meshes (the scene's folder, the working folder, -L folders,
// POV-Ray's includes, the output folder; --allow-read widens them), and scene text printed
// with its control characters escaped and its long tokens cut.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/cli.hpp"

namespace convray {
namespace {

namespace fs = std::filesystem;

const std::string kSoup = std::string(CONVRAY_SOURCE_DIR) + "/scenes/models/soup.obj";

class SceneReads : public testing::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    fs::create_directories(dir_ / "scene");
    fs::create_directories(dir_ / "elsewhere");
    fs::create_directories(dir_ / "out");
    std::ofstream(file("elsewhere/secret.inc")) << "first line of another file\n";
    fs::copy_file(kSoup, dir_ / "elsewhere" / "soup.obj");
  }
  void write_scene(const std::string& body) const {
    std::ofstream(file("scene/s.pov"))
        << "camera { location <0, 0, -4> look_at 0 }\nlight_source { <0, 4, -4> color rgb 1 }\n"
        << body;
  }
  // Renders scene/s.pov from the test's folder `from` (relative to dir_).
  testing::CliRun render(const std::string& from, const std::string& extra = "") const {
    return run_convray_after("cd '" + (dir_ / from).string() + "' && ",
                             "'" + file("scene/s.pov") + "' -o '" + file("out/s.png") +
                                 "' +W16 +H12 " + extra);
  }
};

TEST_F(SceneReads, AnIncludeOutsideTheAllowedFoldersIsRefusedWithoutEchoingIt) {
  write_scene("#include \"../elsewhere/secret.inc\"\n");
  const testing::CliRun run = render("scene");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("s.pov:3:10: cannot read '../elsewhere/secret.inc': it is outside the "
                         "folders a scene may read"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("--allow-read"), std::string::npos) << run.err;
  EXPECT_EQ(run.all().find("first line of another file"), std::string::npos);

  write_scene("#include \"../../../../../../../../etc/passwd\"\n");
  const testing::CliRun passwd = render("scene");
  EXPECT_EQ(passwd.exit_code, 2);
  EXPECT_EQ(passwd.all().find("root:"), std::string::npos) << passwd.err;
  EXPECT_NE(passwd.err.find("outside the folders a scene may read"), std::string::npos);
}

TEST_F(SceneReads, AllowReadWidensTheRule) {
  write_scene("#include \"../elsewhere/secret.inc\"\n");
  const testing::CliRun run =
      render("scene", "--allow-read '" + (dir_ / "elsewhere").string() + "'");
  // Now the file is read: it is not a scene, so its first token is the error.
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.find("outside the folders"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("secret.inc:1:1"), std::string::npos) << run.err;
  const testing::CliRun anywhere = render("scene", "--allow-read-anywhere");
  EXPECT_NE(anywhere.err.find("secret.inc:1:1"), std::string::npos) << anywhere.err;
}

TEST_F(SceneReads, TheWorkingOutputAndLibraryFoldersMayBeRead) {
  write_scene("#include \"secret.inc\"\n");
  fs::create_directories(dir_ / "out");
  fs::copy_file(file("elsewhere/secret.inc"), file("out/secret.inc"));
  // Found through -L, and read: the error is inside the file, not about the rule.
  EXPECT_NE(render("scene", "-L '" + file("elsewhere") + "'").err.find("secret.inc:1:1"),
            std::string::npos);
  // The working folder: an include named from there.
  write_scene("#include \"" + file("elsewhere/secret.inc") + "\"\n");
  EXPECT_NE(render("elsewhere").err.find("secret.inc:1:1"), std::string::npos);
  // The output folder.
  write_scene("#include \"" + file("out/secret.inc") + "\"\n");
  EXPECT_NE(render("scene").err.find("secret.inc:1:1"), std::string::npos);
}

TEST_F(SceneReads, MeshesFollowTheSameRuleAndSymlinksDoNotEscapeIt) {
  write_scene("convolution { radius 0.25 mesh { \"../elsewhere/soup.obj\" } }\n");
  const testing::CliRun outside = render("scene");
  EXPECT_EQ(outside.exit_code, 2);
  EXPECT_NE(outside.err.find("outside the folders a scene may read"), std::string::npos)
      << outside.err;
  // A link inside the scene's folder that points out of it is judged by where it points.
  fs::create_directory_symlink(dir_ / "elsewhere", dir_ / "scene" / "link");
  write_scene("convolution { radius 0.25 mesh { \"link/soup.obj\" } }\n");
  const testing::CliRun linked = render("scene");
  EXPECT_EQ(linked.exit_code, 2);
  EXPECT_NE(linked.err.find("outside the folders a scene may read"), std::string::npos)
      << linked.err;
  fs::copy_file(kSoup, dir_ / "scene" / "soup.obj");
  write_scene("convolution { radius 0.25 mesh { \"soup.obj\" } }\n");
  EXPECT_EQ(render("scene").exit_code, 0);
}

// A folder, a named pipe, a device (through a link to /dev/zero) and a loop of links, given as
// an include, as a scene's mesh, as the mesh of quick and info, and as the scene: each named
// for what it is, exit 2, at once (neither waiting for the pipe's writer nor reading /dev/zero
// forever), never "file not found".
TEST_F(SceneReads, FoldersPipesDevicesAndLinkLoopsAreNamedForWhatTheyAre) {
  fs::create_directories(dir_ / "scene" / "folder.obj");
  ASSERT_EQ(::mkfifo(file("scene/pipe.obj").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir_ / "scene" / "zero.obj");
  fs::create_symlink("loop2.obj", dir_ / "scene" / "loop1.obj");
  fs::create_symlink("loop1.obj", dir_ / "scene" / "loop2.obj");
  const std::pair<std::string, std::string> kinds[] = {
      {"folder.obj", "is a folder, not a file"},
      {"pipe.obj", "is a named pipe, not a file"},
      {"zero.obj", "is a character device, not a file"},
      {"loop1.obj", "is a loop of symbolic links"}};
  auto expect_named = [&](const std::string& arguments, const std::string& what) {
    bool timed_out = false;
    const testing::CliRun run =
        run_convray_limited(arguments, uint64_t(4) << 30, 30, "", &timed_out);
    EXPECT_FALSE(timed_out) << arguments;
    EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.err;
    EXPECT_NE(run.err.find(what), std::string::npos) << arguments << "\n" << run.err;
    EXPECT_EQ(run.err.find("not found"), std::string::npos) << run.err;
  };
  for (const auto& [name, what] : kinds) {
    for (const std::string& body :
         {"#include \"" + name + "\"\n",
          "convolution { radius 0.25 mesh { \"" + name + "\" } pigment { rgb 1 } }\n"}) {
      write_scene(body);
      expect_named("scene/s.pov -o out/s.png +W16 +H12 --allow-read-anywhere", what);
    }
    expect_named("quick scene/" + name + " --size 16x12 -o out/q.png", what);
    expect_named("info scene/" + name, what);
    expect_named("scene/" + name + " -o out/s.png +W16 +H12", what);
  }
}

TEST_F(SceneReads, SceneTextReachesTheTerminalEscaped) {
  write_scene("#debug concat(chr(27), \"[2J cleared?\\n\")\n");
  const testing::CliRun debug = render("scene");
  EXPECT_EQ(debug.exit_code, 0) << debug.err;
  EXPECT_EQ(debug.all().find('\x1b'), std::string::npos);
  EXPECT_NE(debug.err.find("\\x1b[2J cleared?"), std::string::npos) << debug.err;

  write_scene("#error concat(\"bad\", chr(7), chr(27), \"]0;title\")\n");
  const testing::CliRun error = render("scene");
  EXPECT_EQ(error.exit_code, 2);
  EXPECT_EQ(error.all().find('\x1b'), std::string::npos);
  EXPECT_EQ(error.all().find('\x07'), std::string::npos);
  EXPECT_NE(error.err.find("bad\\x07\\x1b]0;title"), std::string::npos) << error.err;
}

TEST_F(SceneReads, AHugeTokenIsCutInTheMessage) {
  // A token as long as a line may be (4096 characters): echoed cut, with its length.
  const std::string huge(4000, 'x');
  const testing::CliRun run =
      run_convray("field --mesh '" + kSoup + "' --radius 0.25", "0 0 " + huge + "\n");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_LT(run.err.size(), 2000u) << run.err.substr(0, 400);
  EXPECT_NE(run.err.find("bytes)"), std::string::npos) << run.err.substr(0, 400);
  // Longer, the line itself is refused before any of it is echoed (issue 17).
  const testing::CliRun longer = run_convray("field --mesh '" + kSoup + "' --radius 0.25",
                                             "0 0 " + std::string(10'000'000, 'x') + "\n");
  EXPECT_EQ(longer.exit_code, 2);
  EXPECT_EQ(longer.err, "stdin:1: the line is longer than 4096 characters\n");
}

}  // namespace
}  // namespace convray
