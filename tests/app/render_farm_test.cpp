// The render-farm recipes of docs/render-farm.md, run as a user would: the GNU parallel script
// on this machine's cores, and the Slurm job-array script with a stand-in `sbatch` (it records
// what it was asked to submit) and each array task run as Slurm would run it. Either way the
// frames must be byte-identical to one process rendering them all. (Against Slurm itself, on a
// single-node cluster the test starts: tests/slurm/render_farm_slurm_test.sh.)
#include <gtest/gtest.h>

#include <set>

#include "cli.hpp"

namespace convray::testing {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = R"(
camera { location <0, 1, -5> look_at 0 }
light_source { <4, 6, -5> color rgb 1 }
blob { threshold 0.5
  sphere { <-1.2 + 2.4*clock, 0, 0>, 1.1, 1 }  sphere { <0.6, 0.4, 0.3>, 1, 1 }
  pigment { rgb <0.3, 0.6, 0.9> } finish { phong 0.4 } }
plane { y, -1.2 pigment { checker rgb 1 rgb 0.3 } }
)";

constexpr const char* kAnimation =
    "Input_File_Name=scene.pov\nOutput_File_Name=frames/\nWidth=48\nHeight=36\n"
    "Antialias=on\nAntialias_Threshold=0.1\nFinal_Frame=7\nCyclic_Animation=on\n";

std::string quote(const std::string& s) { return "'" + s + "'"; }

class RenderFarm : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    std::ofstream(file("scene.pov")) << kScene;
    std::ofstream(file("anim.ini")) << kAnimation;
    // The reference: one process, every frame.
    fs::create_directories(dir_ / "single");
    fs::copy_file(file("scene.pov"), dir_ / "single/scene.pov");
    fs::copy_file(file("anim.ini"), dir_ / "single/anim.ini");
    EXPECT_EQ(sh("cd single && " + quote(CONVRAY_BINARY) + " anim.ini --quiet"), 0);
  }

  int sh(const std::string& command, std::string* log = nullptr) const {
    const std::string line = "cd " + quote(dir_.string()) +
                             " && export CONVRAY=" + quote(CONVRAY_BINARY) + " && (" + command +
                             ") > " + quote((dir_ / ".log").string()) + " 2>&1";
    const int status = std::system(line.c_str());
    if (log) *log = read_file(dir_ / ".log");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  static std::string script(const std::string& name) {
    return quote(std::string(CONVRAY_SOURCE_DIR) + "/scripts/" + name);
  }

  void expect_same_frames_as_single() const {
    std::set<std::string> single, farm;
    for (const auto& e : fs::directory_iterator(dir_ / "single/frames")) {
      single.insert(e.path().filename());
    }
    for (const auto& e : fs::directory_iterator(dir_ / "frames")) farm.insert(e.path().filename());
    EXPECT_EQ(single.size(), 7u);
    EXPECT_EQ(farm, single);
    for (const std::string& name : single) {
      EXPECT_EQ(read_file(dir_ / "frames" / name), read_file(dir_ / "single/frames" / name))
          << name;
    }
  }
};

TEST_F(RenderFarm, GnuParallelRecipeGivesTheSameFrames) {
  if (sh("command -v parallel") != 0) GTEST_SKIP() << "GNU parallel is not installed";
  std::string log;
  ASSERT_EQ(sh("bash " + script("render-farm-parallel.sh") + " anim.ini -j3", &log), 0) << log;
  expect_same_frames_as_single();
  // A rerun finds every frame complete and renders nothing.
  const auto before = fs::last_write_time(dir_ / "frames/scene3.png");
  ASSERT_EQ(sh("bash " + script("render-farm-parallel.sh") + " anim.ini -j3", &log), 0) << log;
  EXPECT_EQ(fs::last_write_time(dir_ / "frames/scene3.png"), before);
}

TEST_F(RenderFarm, SlurmArrayScriptSubmitsChunksAndEachTaskRendersItsOwn) {
  // A stand-in sbatch on PATH records its arguments.
  fs::create_directories(dir_ / "bin");
  std::ofstream(file("bin/sbatch")) << "#!/bin/sh\nprintf '%s\\n' \"$@\" > sbatch.args\n";
  fs::permissions(dir_ / "bin/sbatch", fs::perms::owner_all);
  std::string log;
  ASSERT_EQ(sh("PATH=\"$PWD/bin:$PATH\" bash " + script("render-farm-slurm.sh") +
                   " submit anim.ini 3 -- --partition=render",
               &log),
            0)
      << log;
  EXPECT_NE(log.find("7 frames, 3 array tasks"), std::string::npos) << log;
  const std::string args = read_file(dir_ / "sbatch.args");
  EXPECT_NE(args.find("--array=0-2\n--partition=render\n"), std::string::npos) << args;
  EXPECT_NE(args.find("task\nanim.ini\n3\n"), std::string::npos) << args;
  // Slurm runs the tasks in any order, on any node: here last first.
  for (const char* task : {"2", "0", "1"}) {
    ASSERT_EQ(sh(std::string("SLURM_ARRAY_TASK_ID=") + task + " SLURM_CPUS_PER_TASK=1 bash " +
                     script("render-farm-slurm.sh") + " task anim.ini 3",
                 &log),
              0)
        << log;
  }
  expect_same_frames_as_single();
  // A task past the end has nothing to do and says so.
  ASSERT_EQ(
      sh("SLURM_ARRAY_TASK_ID=5 bash " + script("render-farm-slurm.sh") + " task anim.ini 3", &log),
      0);
  EXPECT_NE(log.find("no frames left"), std::string::npos) << log;
}

}  // namespace
}  // namespace convray::testing
