// `convray slice`: writes a picture only when everything is right, never a partial file,
// and says what is wrong otherwise.
#include <filesystem>
#include <fstream>
#include <string>

#include "app/cli.hpp"

namespace convray {
namespace {

class SliceCommand : public testing::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    std::ofstream(file("tri.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  }
  bool no_partial_files() const {
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
      if (entry.path().filename().string().find(".partial") != std::string::npos) return false;
    }
    return true;
  }
};

// Width and height from a PNG's IHDR chunk (bytes 16..23, big-endian): independent of OIIO.
std::pair<int, int> png_size(const std::string& bytes) {
  const auto be32 = [&](size_t at) {
    return int((unsigned char)bytes[at]) << 24 | int((unsigned char)bytes[at + 1]) << 16 |
           int((unsigned char)bytes[at + 2]) << 8 | int((unsigned char)bytes[at + 3]);
  };
  return bytes.size() >= 24 && bytes.compare(1, 3, "PNG") == 0 ? std::pair{be32(16), be32(20)}
                                                                : std::pair{-1, -1};
}

TEST_F(SliceCommand, WritesAPngOfTheRequestedSize) {
  const testing::CliRun run =
      run_convray("slice '" + file("tri.obj") + "' --radius 0.3 --size 64x48 -o '" + file("s.png") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_EQ(png_size(testing::read_file(file("s.png"))), (std::pair{64, 48}));
  EXPECT_NE(run.out.find("wrote"), std::string::npos);
  EXPECT_TRUE(no_partial_files());
}

TEST_F(SliceCommand, UnknownImageFormatFailsWithoutWritingAnything) {
  const testing::CliRun run =
      run_convray("slice '" + file("tri.obj") + "' --radius 0.3 -o '" + file("s.notanimage") + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("s.notanimage"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(file("s.notanimage")));
  EXPECT_TRUE(no_partial_files());
}

TEST_F(SliceCommand, MissingOutputFolderFailsCleanly) {
  const testing::CliRun run = run_convray("slice '" + file("tri.obj") + "' --radius 0.3 -o '" +
                                          file("no/such/folder/s.png") + "'");
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("s.png"), std::string::npos) << run.err;
}

TEST_F(SliceCommand, RejectsBadOptionsWithExitCode2) {
  const std::string mesh = "'" + file("tri.obj") + "'";
  testing::CliRun run = run_convray("slice " + mesh + " --radius 0.3 --offset 0.3");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--offset must satisfy 0 <= offset < radius"), std::string::npos) << run.err;
  run = run_convray("slice " + mesh + " --radius 0.3 --size 64by48");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("WIDTHxHEIGHT"), std::string::npos) << run.err;
  run = run_convray("slice " + mesh + " --radius 0.3 --axis w");
  EXPECT_EQ(run.exit_code, 2);
  run = run_convray("slice " + mesh + " --radius 0.3 --offset 0.1 --threshold 0.2");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("excludes"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace convray
