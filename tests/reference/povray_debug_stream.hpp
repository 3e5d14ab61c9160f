#pragma once
// The installed POV-Ray 3.7 run on a scene text, read through what its #debug directives
// print: POV-Ray's debug stream (+GD to a file; a 1x1 render without an output file). Tests
// that compare with POV-Ray skip when povray is not installed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace convray::povray_testing {

inline bool povray_installed() {
  static const bool installed = std::system("povray --version > /dev/null 2>&1") == 0;
  return installed;
}

#define SKIP_WITHOUT_POVRAY()                                                   \
  if (!::convray::povray_testing::povray_installed())                     \
  GTEST_SKIP() << "povray is not installed (scripts/setup.sh installs it); "   \
                  "this test compares with POV-Ray 3.7's own output"

struct PovRayRun {
  int exit_code = -1;
  std::string debug;     // everything #debug printed
  std::string messages;  // the console: warnings and errors
};

// Runs POV-Ray on `scene` (written to a private folder) and returns its debug stream and
// console messages.
inline PovRayRun povray_run(const std::string& scene) {
  namespace fs = std::filesystem;
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path folder = fs::temp_directory_path() /
                          ("convray_povray_" + std::to_string(::getpid()) + "_" + test->name());
  fs::create_directories(folder);
  std::ofstream(folder / "scene.pov") << scene;
  const std::string command = "cd '" + folder.string() +
                              "' && povray +Iscene.pov +W1 +H1 -F -D -GA +GDdebug.txt "
                              "+GWwarnings.txt +GFwarnings.txt > console.txt 2>&1";
  PovRayRun run;
  const int status = std::system(command.c_str());
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const auto read = [&](const char* name) {
    std::ifstream in(folder / name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  run.debug = read("debug.txt");
  run.messages = read("warnings.txt") + read("console.txt");
  fs::remove_all(folder);
  return run;
}

}  // namespace convray::povray_testing
