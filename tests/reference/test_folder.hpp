#pragma once
// A folder of the running test's own under the system's temporary folder, made empty when the
// object is made (left over from an earlier run or not) and removed with it. Its name holds
// `tag` (the suite's), the process id and the test's name, so that tests of different suites,
// and the same test run twice at once, never share one.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace convray::testing {

class TestFolder {
 public:
  explicit TestFolder(const std::string& tag)
      : path_(std::filesystem::temp_directory_path() /
              ("convray-" + tag + "-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TestFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TestFolder(const TestFolder&) = delete;
  TestFolder& operator=(const TestFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace convray::testing
