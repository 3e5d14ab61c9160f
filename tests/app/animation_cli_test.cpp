// Animations through the program, as users and render farms run them:
//  - every animation option set gives the clock identifiers and file names POV-Ray 3.7 gives
//    (the povray binary is run on the same scene and switches, when installed);
//  - a render killed mid-frame and restarted with +C ends byte-identical to an uninterrupted
//    one, and never keeps a truncated frame;
//  - two processes rendering disjoint subsets at once write the same bytes as one process;
//  - INI mistakes stop before any image is written; --video needs ffmpeg and says so.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <regex>
#include <set>
#include <thread>

#include "cli.hpp"

extern char** environ;

namespace convray::testing {
namespace {

namespace fs = std::filesystem;

// Prints every animation identifier; POV-Ray and convray both run it.
constexpr const char* kClockScene = R"(
#debug concat("F ", str(frame_number,0,0), " C ", str(clock,0,6), " D ", str(clock_delta,0,6),
  " ON ", str(clock_on,0,0), " IF ", str(initial_frame,0,0), " FF ", str(final_frame,0,0),
  " IC ", str(initial_clock,0,4), " FC ", str(final_clock,0,4), "\n")
sphere { 0, 1 pigment { rgb 1 } }
camera { location -5*z look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
)";

// A scene that takes a moment per frame (a blob, supersampled everywhere), moving with clock.
constexpr const char* kSlowScene = R"(
camera { location <0, 0, -6> look_at 0 }
light_source { <4, 6, -5> color rgb 1 }
blob { threshold 0.6
  sphere { <-1 + 2*clock, 0, 0>, 1.2, 1 }  sphere { <1, 0.3, 0>, 1.1, 1 }
  cylinder { <-1, -1, 0>, <1, -1, 0.5>, 0.6, 1 }
  pigment { rgb <0.9, 0.5, 0.3> } finish { phong 0.5 } }
plane { y, -2 pigment { checker rgb 1 rgb 0.2 } }
)";

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The frame lines "F .. C .. " in order, each split into its 8 numbers.
std::vector<std::vector<double>> identifier_lines(const std::string& output) {
  static const std::regex line(
      R"(F (-?\d+) C (\S+) D (\S+) ON (\d) IF (-?\d+) FF (-?\d+) IC (\S+) FC (\S+))");
  std::vector<std::vector<double>> lines;
  for (auto it = std::sregex_iterator(output.begin(), output.end(), line);
       it != std::sregex_iterator(); ++it) {
    std::vector<double> numbers;
    for (size_t k = 1; k <= 8; ++k) numbers.push_back(std::stod((*it)[k].str()));
    lines.push_back(numbers);
  }
  return lines;
}

bool have(const std::string& program) {
  return std::system(("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
}

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
  return names;
}

class AnimationCli : public CliTest {
 protected:
  // Runs a shell command in the test's folder; its exit code, output in `log`.
  int shell(const std::string& command, std::string* log = nullptr) const {
    const std::string line = "cd " + shell_quote(dir_.string()) + " && (" + command + ") > " +
                             shell_quote((dir_ / ".log").string()) + " 2>&1";
    const int status = std::system(line.c_str());
    if (log) *log = read_file(dir_ / ".log");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string convray() const { return shell_quote(CONVRAY_BINARY); }

  // Starts `convray ARGS` in `folder` in the background; its process id.
  pid_t start(const fs::path& folder, const std::string& arguments) const {
    const std::string line = "cd " + shell_quote(folder.string()) + " && exec " + convray() + " " +
                             arguments + " > /dev/null 2>&1";
    const char* argv[] = {"/bin/sh", "-c", line.c_str(), nullptr};
    pid_t pid = 0;
    EXPECT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ), 0);
    return pid;
  }
  static int wait_for(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
};

TEST_F(AnimationCli, ClockIdentifiersAndFileNamesMatchPovRay) {
  if (!have("povray")) GTEST_SKIP() << "povray is not installed (scripts/setup.sh installs it)";
  std::ofstream(file("c.pov")) << kClockScene;
  const std::vector<std::string> option_sets = {
      "",
      "+K0.7",
      "+KFF5",
      "+KFF5 +KC",
      "+KFF9 +KC",
      "+KFI3 +KFF12 +KI2 +KF4",
      "+KFF5 +KI1 +KF0",
      "+KFF4 +KI2 +KF-2 +KC",
      "+KFF10 +SF3 +EF5",
      "+KFF12 +SF0.3 +EF0.6",
      "+KFI0 +KFF10 +SF0.3 +EF0.6",
      "+KFI5 +KFF15 +SF0.25 +EF0.75",
      "+KFI10 +KFF30 +SF0.5 +EF0.9",
      "+KFF10 +SF0.5",
      "+KFF10 +EF0.5",
      "+KFF10 +SF1.0 +EF1.0",
      "+KFF10 Frame_Step=3",
      "+KFF10 +SF2 Frame_Step=3",
      "+KFI4 +KFF10 +KC +SF5 +EF7",
      "+KFF10 +KC +SF0.5 +EF0.99",
      "+KFF5 +K0.3",
      "+KFI-3 +KFF3",
      "+KI0.5 +KF2",
      "+KC",
      "+KFI2 +KFF4 +SF3",
      "+KFF100 +SF98",
  };
  // POV-Ray spends most of a tiny render waiting, so every option set runs at once, each in
  // folders of its own; then convray runs the same sets.
  std::string all_povray_runs;
  for (size_t i = 0; i < option_sets.size(); ++i) {
    for (const std::string who : {"pov", "ours"}) {
      const fs::path folder = dir_ / (who + std::to_string(i));
      fs::create_directories(folder);
      fs::copy_file(dir_ / "c.pov", folder / "c.pov");
    }
    all_povray_runs += "(cd pov" + std::to_string(i) + " && povray +Ic.pov +W8 +H6 -D -P " +
                       option_sets[i] + " > log 2>&1) & ";
  }
  shell(all_povray_runs + "wait");
  for (size_t i = 0; i < option_sets.size(); ++i) {
    SCOPED_TRACE("options: " + option_sets[i]);
    const fs::path pov_folder = dir_ / ("pov" + std::to_string(i));
    const fs::path our_folder = dir_ / ("ours" + std::to_string(i));
    const std::string pov_log = read_file(pov_folder / "log");
    fs::remove(pov_folder / "log");
    std::string our_log;
    ASSERT_EQ(
        shell("cd " + our_folder.string() + " && " + convray() + " c.pov +W8 +H6 " + option_sets[i],
              &our_log),
        0)
        << our_log;
    const auto pov = identifier_lines(pov_log), ours = identifier_lines(our_log);
    ASSERT_FALSE(pov.empty()) << pov_log;
    ASSERT_EQ(ours.size(), pov.size()) << our_log << "\n--- povray:\n" << pov_log;
    for (size_t f = 0; f < pov.size(); ++f) {
      for (size_t k = 0; k < 8; ++k) {
        EXPECT_NEAR(ours[f][k], pov[f][k], 1e-6 * (1 + std::abs(pov[f][k])))
            << "frame line " << f << ", value " << k;
      }
    }
    EXPECT_EQ(files_in(our_folder), files_in(pov_folder));
  }
}

TEST_F(AnimationCli, OutputFoldersAndNamesAsPovRay) {
  std::ofstream(file("c.pov")) << kClockScene;
  ASSERT_EQ(shell(convray() + " c.pov +W8 +H6 +KFF12 +SF11 +Oframes/run/"), 0);
  EXPECT_EQ(files_in(dir_ / "frames/run"), (std::set<std::string>{"c11.png", "c12.png"}));
  ASSERT_EQ(shell(convray() + " c.pov +W8 +H6 +KFF3 -o shot.exr"), 0);
  EXPECT_TRUE(fs::exists(dir_ / "shot1.exr") && fs::exists(dir_ / "shot3.exr"));
}

TEST_F(AnimationCli, DisjointSubsetsInParallelEqualOneProcess) {
  std::ofstream(file("slow.pov")) << kSlowScene;
  fs::create_directories(dir_ / "farm");
  fs::create_directories(dir_ / "single");
  const std::string common = "../slow.pov +W64 +H48 +A0.1 +KFF6 +WT1";
  const pid_t first = start(dir_ / "farm", common + " +SF1 +EF3");
  const pid_t second = start(dir_ / "farm", common + " +SF4 +EF6");
  ASSERT_EQ(wait_for(first), 0);
  ASSERT_EQ(wait_for(second), 0);
  ASSERT_EQ(shell("cd single && " + convray() + " " + common), 0);
  const std::set<std::string> names = files_in(dir_ / "single");
  ASSERT_EQ(names.size(), 6u);
  EXPECT_EQ(files_in(dir_ / "farm"), names);
  for (const std::string& name : names) {
    EXPECT_EQ(read_file(dir_ / "farm" / name), read_file(dir_ / "single" / name)) << name;
  }
}

TEST_F(AnimationCli, KilledMidFrameThenContinuedEqualsAnUninterruptedRun) {
  std::ofstream(file("slow.pov")) << kSlowScene;
  fs::create_directories(dir_ / "resumed");
  fs::create_directories(dir_ / "whole");
  const std::string common = "../slow.pov +W160 +H120 +A0.0 +R4 +KFF5 +WT1";
  const pid_t pid = start(dir_ / "resumed", common);
  // Kill it while frame 3 renders: as soon as frame 2 is complete.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(dir_ / "resumed/slow2.png") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(fs::exists(dir_ / "resumed/slow2.png"));
  kill(pid, SIGKILL);
  wait_for(pid);
  EXPECT_FALSE(fs::exists(dir_ / "resumed/slow5.png")) << "the render finished before the kill";
  const fs::file_time_type first_frame_time = fs::last_write_time(dir_ / "resumed/slow1.png");

  std::string log;
  ASSERT_EQ(shell("cd resumed && " + convray() + " " + common + " +C", &log), 0) << log;
  EXPECT_NE(log.find("slow1.png is complete; skipped (+C)"), std::string::npos) << log;
  EXPECT_EQ(fs::last_write_time(dir_ / "resumed/slow1.png"), first_frame_time);  // not redone
  ASSERT_EQ(shell("cd whole && " + convray() + " " + common), 0);
  const std::set<std::string> names = files_in(dir_ / "whole");
  EXPECT_EQ(names.size(), 5u);
  EXPECT_EQ(files_in(dir_ / "resumed"), names);  // nothing partial left behind
  for (const std::string& name : names) {
    EXPECT_EQ(read_file(dir_ / "resumed" / name), read_file(dir_ / "whole" / name)) << name;
  }
}

TEST_F(AnimationCli, ContinueRendersATruncatedOrMissizedFrameAgain) {
  std::ofstream(file("c.pov")) << kClockScene;
  ASSERT_EQ(shell(convray() + " c.pov +W16 +H12 +KFF3"), 0);
  const std::string good = read_file(dir_ / "c2.png");
  std::ofstream(file("c2.png"), std::ios::binary) << good.substr(0, good.size() / 2);
  std::string log;
  ASSERT_EQ(shell(convray() + " c.pov +W16 +H12 +KFF3 +C", &log), 0);
  EXPECT_EQ(read_file(dir_ / "c2.png"), good) << log;
  EXPECT_NE(log.find("c1.png is complete"), std::string::npos);
  // Another size is not the frame asked for.
  ASSERT_EQ(shell(convray() + " c.pov +W20 +H12 +KFF3 +C", &log), 0);
  EXPECT_EQ(log.find("is complete"), std::string::npos) << log;
}

TEST_F(AnimationCli, IniMistakesStopBeforeAnyImage) {
  std::ofstream(file("c.pov")) << kClockScene;
  std::ofstream(file("anim.ini")) << "Input_File_Name=c.pov\nFinal_Frame=3\nWidth=8\n"
                                     "Height=6\nFinal_Clock=one\n";
  std::string log;
  EXPECT_EQ(shell(convray() + " anim.ini", &log), 2);
  EXPECT_NE(log.find("anim.ini:5:13: Final_Clock: expected a number, got 'one'"), std::string::npos)
      << log;
  EXPECT_FALSE(fs::exists(dir_ / "c1.png"));
  std::ofstream(file("anim.ini")) << "Input_File_Name=c.pov\nFinal_Frame=2\nWidth=8\nHeight=6\n";
  EXPECT_EQ(shell(convray() + " anim.ini[Missing]", &log), 2);
  EXPECT_NE(log.find("has no section [Missing]"), std::string::npos) << log;
  EXPECT_EQ(shell(convray() + " anim.ini", &log), 0) << log;
  EXPECT_TRUE(fs::exists(dir_ / "c1.png") && fs::exists(dir_ / "c2.png"));
}

TEST_F(AnimationCli, VideoNeedsFfmpegAndSaysSoBeforeRendering) {
  std::ofstream(file("c.pov")) << kClockScene;
  std::string log;
  EXPECT_EQ(shell("PATH=/nonexistent " + convray() + " c.pov +W8 +H6 +KFF3 --video a.mp4", &log),
            2);
  EXPECT_NE(log.find("--video needs ffmpeg, which is not installed"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir_ / "c1.png"));
  if (!have("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed";
  ASSERT_EQ(shell(convray() + " c.pov +W9 +H7 +KFF6 Frame_Step=2 --video clip.mp4 --fps 10", &log),
            0)
      << log;
  ASSERT_TRUE(fs::exists(dir_ / "clip.mp4"));
  // ffprobe (part of ffmpeg) counts the frames: 1, 3, 5.
  ASSERT_EQ(shell("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                  "stream=nb_read_frames -of csv=p=0 clip.mp4",
                  &log),
            0);
  EXPECT_EQ(std::stoi(log), 3) << log;
}

}  // namespace
}  // namespace convray::testing
