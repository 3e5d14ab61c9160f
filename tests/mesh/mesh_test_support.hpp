#pragma once
// Helpers shared by the mesh tests: a scratch directory, files from strings, gzip, and
// catching the InputError a call should throw.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "mesh/soup.hpp"
#include "util/error.hpp"

namespace convray::mesh::testing {

// A fresh directory per test, removed afterwards.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("convray-mesh-" + std::to_string(::getpid()) + "-" + test->test_suite_name() + "-" + test->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() { std::filesystem::remove_all(path_); }

  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

// Compresses with zlib's gz file API, as gzip(1) would.
inline void write_gzip(const std::string& path, const std::string& bytes) {
  gzFile file = gzopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  ASSERT_EQ(gzwrite(file, bytes.data(), static_cast<unsigned>(bytes.size())), static_cast<int>(bytes.size()));
  ASSERT_EQ(gzclose(file), Z_OK);
}

// The text of the InputError `call` throws; a test failure if it throws nothing or
// something else.
template <typename Call>
std::string input_error_of(Call&& call) {
  try {
    call();
  } catch (const InputError& error) {
    return error.what();
  } catch (const std::exception& other) {
    ADD_FAILURE() << "expected an InputError, got: " << other.what();
    return "";
  }
  ADD_FAILURE() << "expected an InputError, but nothing was thrown";
  return "";
}

// Rounds every coordinate to a multiple of 1/64, which float32 (binary STL, and assimp's
// storage) holds exactly, so round trips through every format compare exactly.
inline TriangleSoup on_float_grid(TriangleSoup soup) {
  for (Vec3& p : soup.vertices) p = glm::round(p * 64.0) / 64.0;
  return soup;
}

}  // namespace convray::mesh::testing
