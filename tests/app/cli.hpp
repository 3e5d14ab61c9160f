#pragma once
// Runs the built convray binary as a user would, through a shell, in a private temporary
// folder: standard input from a string, standard output and error captured apart.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace convray::testing {

struct CliRun {
  int exit_code = -1;
  std::string out, err;
  std::string all() const { return out + err; }
};

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fixture owning a fresh folder per test, removed afterwards.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("convray-cli-" + std::to_string(::getpid()) + "-" + info->test_suite_name() + "-" +
            info->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  // `convray ARGUMENTS < stdin_text`; ARGUMENTS is shell text (quote paths yourself).
  CliRun run_convray(const std::string& arguments, const std::string& stdin_text = "") const {
    return run_convray_after("", arguments, stdin_text);
  }

  // The same, after the shell text `prefix` (e.g. "cd FOLDER && ").
  CliRun run_convray_after(const std::string& prefix, const std::string& arguments,
                           const std::string& stdin_text = "") const {
    std::ofstream(dir_ / ".stdin") << stdin_text;
    const std::string command = prefix + "'" + std::string(CONVRAY_BINARY) + "' " + arguments +
                                " < '" + (dir_ / ".stdin").string() + "' > '" +
                                (dir_ / ".stdout").string() + "' 2> '" +
                                (dir_ / ".stderr").string() + "'";
    const int status = std::system(command.c_str());
    CliRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = read_file(dir_ / ".stdout");
    run.err = read_file(dir_ / ".stderr");
    return run;
  }

  std::filesystem::path dir_;
};

}  // namespace convray::testing
