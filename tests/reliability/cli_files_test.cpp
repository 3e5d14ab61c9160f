// The program as a render farm and a shared machine use it (issue 20): a full disk (a
// file-size limit, `ulimit -f`, fails every write past it as a full disk does), two
// processes writing one name, a symlink planted in a shared folder, leftovers of killed runs,
// devices as outputs. Each time: the previous file is untouched or replaced whole, the
// command says what happened and exits non-zero, and no temporary is left behind.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/cli.hpp"

namespace convray {
namespace {

namespace fs = std::filesystem;

const std::string kSoup = "'" + std::string(CONVRAY_SOURCE_DIR) + "/scenes/models/soup.obj'";

// A sphere on a plane; `colour` tells two renders apart.
std::string scene_text(const std::string& colour) {
  return "#version 3.7;\n"
         "global_settings { assumed_gamma 1.0 }\n"
         "camera { location <0, 1, -4> look_at <0, 0.5, 0> }\n"
         "light_source { <-4, 6, -5> color rgb 1 }\n"
         "plane { y, -0.5 pigment { checker color rgb 0.9 color rgb 0.4 } }\n"
         "sphere { <0, 0.5, 0>, 1 pigment { color rgb " + colour +
         " } finish { phong 0.8 } }\n";
}

class FilesUnderStress : public testing::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    std::ofstream(file("a.pov")) << scene_text("<1, 0.3, 0.2>");
    std::ofstream(file("b.pov")) << scene_text("<0.2, 0.4, 1>");
  }
  // Names in the folder that are neither the test's own files nor finished outputs.
  std::vector<std::string> temporaries() const {
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      if (name.find(".partial") != std::string::npos || name.find(".tmp.") != std::string::npos)
        found.push_back(name);
    }
    return found;
  }
  // `convray ARGS` under a file-size limit of `kib` KiB: every write past it fails (EFBIG).
  testing::CliRun run_with_file_limit(int kib, const std::string& arguments) const {
    return run_convray_after("cd '" + dir_.string() + "' && ulimit -f " + std::to_string(kib) +
                                 " && ",
                             arguments);
  }
  void keep_good_file(const std::string& name) const {
    std::ofstream(file(name), std::ios::binary) << "the user's good file";
  }
  std::string contents(const std::string& name) const { return testing::read_file(file(name)); }
  // Runs a bash script in the test's folder, `$CONVRAY` naming the program; its exit status.
  int run_script(const std::string& text) const {
    std::ofstream(file("script.sh")) << "set -u\ncd '" << dir_.string() << "'\nCONVRAY='"
                                     << CONVRAY_BINARY << "'\n" << text << "\n";
    const int status = std::system(("bash '" + file("script.sh") + "'").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
};

TEST_F(FilesUnderStress, AFullDiskKeepsTheGoodImageAndSaysSo) {
  keep_good_file("keep.png");
  const testing::CliRun run = run_with_file_limit(1, "a.pov -o keep.png +W320 +H240 -A");
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("keep.png: cannot write the image: File too large"), std::string::npos)
      << run.err;
  EXPECT_EQ(run.out.find("wrote"), std::string::npos) << run.out;
  EXPECT_EQ(contents("keep.png"), "the user's good file");
  EXPECT_TRUE(temporaries().empty());
}

TEST_F(FilesUnderStress, AFullDiskStopsAnAnimationAtTheFirstFrame) {
  fs::create_directory(dir_ / "frames");
  keep_good_file("frames/f1.png");
  const testing::CliRun run =
      run_with_file_limit(1, "a.pov -o frames/f.png +W320 +H240 -A +KFI1 +KFF3");
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("f1.png: cannot write the image"), std::string::npos) << run.err;
  EXPECT_EQ(contents("frames/f1.png"), "the user's good file");
  EXPECT_FALSE(fs::exists(dir_ / "frames" / "f2.png"));  // stopped at the first failure
  EXPECT_FALSE(fs::exists(dir_ / "frames" / "f3.png"));
  EXPECT_TRUE(temporaries().empty());
}

TEST_F(FilesUnderStress, AFullDiskFailsQuickSliceAndPolygonizeCleanly) {
  const std::vector<std::pair<std::string, std::string>> commands = {
      {"q.png", "quick " + kSoup + " --radius 0.25 --size 200x150 -o q.png"},
      {"s.png", "slice " + kSoup + " --radius 0.25 --size 200x150 -o s.png"},
      {"p.obj", "polygonize " + kSoup + " --radius 0.25 --offset 0.1 --cell 0.05 -o p.obj"},
  };
  for (const auto& [output, command] : commands) {
    keep_good_file(output);
    const testing::CliRun run = run_with_file_limit(1, command);
    EXPECT_NE(run.exit_code, 0) << command;
    EXPECT_NE(run.err.find(output + ": cannot write"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("File too large"), std::string::npos) << run.err;
    EXPECT_EQ(contents(output), "the user's good file") << command;
    EXPECT_TRUE(temporaries().empty()) << command;
  }
}

TEST_F(FilesUnderStress, ConcurrentWritersOfOneNameLeaveOneWholeRender) {
  ASSERT_EQ(run_convray_after("cd '" + dir_.string() + "' && ", "a.pov -o a.png +W64 +H48 -A")
                .exit_code, 0);
  ASSERT_EQ(run_convray_after("cd '" + dir_.string() + "' && ", "b.pov -o b.png +W64 +H48 -A")
                .exit_code, 0);
  const std::string a = contents("a.png"), b = contents("b.png");
  ASSERT_NE(a, b);
  int won_by_a = 0, won_by_b = 0;
  for (int round = 0; round < 50; ++round) {
    const int status = run_script(
        "\"$CONVRAY\" a.pov -o same.png +W64 +H48 -A --quiet 2> race.err & a=$!\n"
        "\"$CONVRAY\" b.pov -o same.png +W64 +H48 -A --quiet 2>> race.err & b=$!\n"
        "wait $a && wait $b");
    ASSERT_EQ(status, 0) << "round " << round << ": " << contents("race.err");
    const std::string same = contents("same.png");
    ASSERT_TRUE(same == a || same == b) << "round " << round << ": a picture of neither render";
    (same == a ? won_by_a : won_by_b)++;
    ASSERT_TRUE(temporaries().empty()) << "round " << round;
  }
  EXPECT_EQ(won_by_a + won_by_b, 50);
}

TEST_F(FilesUnderStress, ConcurrentAnimationsIntoOneFolderBothFinish) {
  const int status = run_script(
      "mkdir -p out\n"
      "\"$CONVRAY\" a.pov -o out/f.png +W48 +H36 -A +KFI1 +KFF6 --quiet 2> race.err & a=$!\n"
      "\"$CONVRAY\" a.pov -o out/f.png +W48 +H36 -A +KFI1 +KFF6 --quiet 2>> race.err & b=$!\n"
      "wait $a && wait $b");
  EXPECT_EQ(status, 0) << contents("race.err");
  for (int frame = 1; frame <= 6; ++frame) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / ("f" + std::to_string(frame) + ".png")));
  }
  EXPECT_TRUE(temporaries().empty());
}

TEST_F(FilesUnderStress, ASymlinkInASharedFolderNeverRedirectsTheWrite) {
  std::ofstream(file("victim.txt")) << "another user's file";
  fs::create_symlink("victim.txt", dir_ / ".x.partial.png");  // earlier versions' fixed name
  fs::create_symlink("victim.txt", dir_ / "y.png");          // the destination itself
  for (const std::string output : {"x.png", "y.png"}) {
    const testing::CliRun run =
        run_convray_after("cd '" + dir_.string() + "' && ", "a.pov -o " + output + " +W32 +H24");
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir_ / output))) << output;
  }
  EXPECT_EQ(contents("victim.txt"), "another user's file");
}

TEST_F(FilesUnderStress, TheNextRunRemovesWhatAKilledRunLeft) {
  // A run killed by SIGKILL mid-write leaves its temporary; its process is gone.
  const pid_t gone = ::fork();
  if (gone == 0) ::_exit(0);
  ::waitpid(gone, nullptr, 0);
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::string leftover =
      ".out.png.convray." + std::string(host) + "." + std::to_string(gone) + ".deadbeef.partial";
  std::ofstream(file(leftover)) << "";
  const testing::CliRun run =
      run_convray_after("cd '" + dir_.string() + "' && ", "a.pov -o out.png +W32 +H24");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / leftover));
  EXPECT_TRUE(temporaries().empty());
}

TEST_F(FilesUnderStress, AnInterruptedRenderLeavesNoTemporary) {
  // SIGTERM at several moments of a render: before, during and after the write. The good
  // file is either untouched or replaced by a whole render; nothing else is left.
  keep_good_file("out.png");
  for (const std::string delay : {"0.05", "0.2", "0.4", "0.6", "0.8"}) {
    run_script("\"$CONVRAY\" a.pov -o out.png +W800 +H600 +A0.1 --quiet 2>/dev/null & p=$!\n"
               "sleep " + delay + "; kill -TERM $p 2>/dev/null; wait $p");
    const std::string now = contents("out.png");
    EXPECT_TRUE(now == "the user's good file" || now.substr(1, 3) == "PNG") << delay;
    EXPECT_TRUE(temporaries().empty()) << delay;
  }
}

TEST_F(FilesUnderStress, DevicesAreNotOutputs) {
  const testing::CliRun run = run_convray_after("cd '" + dir_.string() + "' && ",
                                                "a.pov -o /dev/full +W32 +H24");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("/dev/full: not a regular file"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists("/dev/full.png"));
  ASSERT_EQ(run_script("mkfifo pipe.png"), 0);
  const testing::CliRun quick =
      run_convray("quick " + kSoup + " --radius 0.25 -o '" + file("pipe.png") + "'");
  EXPECT_EQ(quick.exit_code, 2);
  EXPECT_NE(quick.err.find("a named pipe"), std::string::npos) << quick.err;
}

}  // namespace
}  // namespace convray
