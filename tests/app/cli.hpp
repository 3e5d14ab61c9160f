#pragma once
// Runs the built convray binary as a user would, through a shell, in a private temporary
// folder: standard input from a string, standard output and error captured apart.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

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

  // `convray ARGUMENTS < stdin_text` in the test's folder, with at most `memory_bytes` of
  // address space (RLIMIT_AS, set in the child before exec, as `ulimit -v`) and `seconds` of
  // wall time (then SIGTERM, which removes temporaries, and SIGKILL a second later;
  // timed_out says so). MALLOC_ARENA_MAX=2 keeps glibc from reserving 64 MiB of address space
  // per thread, so the limit means the same on a machine with many cores.
  CliRun run_convray_limited(const std::string& arguments, uint64_t memory_bytes, int seconds,
                             const std::string& stdin_text = "", bool* timed_out = nullptr) const {
    std::ofstream(dir_ / ".stdin") << stdin_text;
    const std::string command = "cd '" + dir_.string() + "' && exec '" +
                                std::string(CONVRAY_BINARY) + "' " + arguments;
    const std::string in = (dir_ / ".stdin").string(), out = (dir_ / ".stdout").string(),
                      err = (dir_ / ".stderr").string();
    const pid_t child = ::fork();
    if (child == 0) {
      const rlimit limit{rlim_t(memory_bytes), rlim_t(memory_bytes)};
      ::setrlimit(RLIMIT_AS, &limit);
      ::setenv("MALLOC_ARENA_MAX", "2", 1);
      ::dup2(::open(in.c_str(), O_RDONLY), 0);
      ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600), 1);
      ::dup2(::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600), 2);
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    bool killed = false;
    while (::waitpid(child, &status, WNOHANG) == 0) {
      if (!killed && std::chrono::steady_clock::now() > deadline) {
        ::kill(child, SIGTERM);
        std::this_thread::sleep_for(std::chrono::seconds(1));
        ::kill(child, SIGKILL);
        killed = true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (timed_out) *timed_out = killed;
    CliRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = read_file(out);
    run.err = read_file(err);
    return run;
  }

  std::filesystem::path dir_;
};

}  // namespace convray::testing
