// Hostile and huge inputs (issue 17), each command under a small address-space limit
// (RLIMIT_AS) and a time limit: a decompression bomb, files larger than memory, jobs whose
// estimate cannot fit, a soup of one triangle a million times, input without line breaks.
// Each time: the message, the exit code, and no temporary left behind.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/cli.hpp"

namespace convray {
namespace {

namespace fs = std::filesystem;

const std::string kSoup = "'" + std::string(CONVRAY_SOURCE_DIR) + "/scenes/models/soup.obj'";
const std::string kSoupScene = "'" + std::string(CONVRAY_SOURCE_DIR) + "/scenes/soup.pov'";

// 1.5 GiB of address space, and 16 MiB more per hardware thread for TBB's workers' stacks:
// convray maps about 0.6 GiB of shared libraries before main, and every case below asks for
// several times this limit.
uint64_t memory_cap() {
  return (uint64_t(3) << 29) + uint64_t(std::thread::hardware_concurrency()) * (16u << 20);
}

constexpr int kSeconds = 90;

class HostileInput : public testing::CliTest {
 protected:
  // `convray ARGUMENTS` under the cap; fails the test if it ran out of time.
  testing::CliRun run(const std::string& arguments, const std::string& stdin_text = "") {
    bool timed_out = false;
    testing::CliRun r =
        run_convray_limited(arguments, memory_cap(), kSeconds, stdin_text, &timed_out);
    EXPECT_FALSE(timed_out) << arguments;
    return r;
  }
  // Names of temporaries (atomic writes' .partial files and folders) left in the folder.
  std::vector<std::string> temporaries() const {
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      if (name.find(".partial") != std::string::npos) found.push_back(name);
    }
    return found;
  }
  // A file of `bytes` that takes no disk space (a hole): larger than any memory.
  void sparse_file(const std::string& name, uint64_t bytes) const {
    std::ofstream(file(name)).close();
    fs::resize_file(file(name), bytes);
  }
  void expect_out_of_memory(const testing::CliRun& r, const std::string& step) const {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("convray: out of memory while " + step), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("terminate called"), std::string::npos) << r.err;
    EXPECT_TRUE(temporaries().empty());
  }
};

// Zeros, `copies` gzip members of 64 MiB each written back to back (gzip -1 makes about
// 280 KiB of each): a valid gzip file that inflates to copies * 64 MiB.
void write_zero_bomb(const std::string& path, int copies) {
  const std::string zeros(64 << 20, '\0');
  uLongf size = compressBound(zeros.size());
  std::string member(size, '\0');
  z_stream z{};
  ASSERT_EQ(deflateInit2(&z, 1, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(zeros.data()));
  z.avail_in = uInt(zeros.size());
  z.next_out = reinterpret_cast<Bytef*>(member.data());
  z.avail_out = uInt(member.size());
  ASSERT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  member.resize(z.total_out);
  deflateEnd(&z);
  std::ofstream out(path, std::ios::binary);
  for (int k = 0; k < copies; ++k) out << member;
}

// 2 GiB of zeros in about 9 MB: the 100-times limit is about 900 MB. A buffer grown by
// doubling held 1.5 GiB at once on the way there, past the cap; counting first holds none.
TEST_F(HostileInput, AGzipBombIsRefusedUnderTheCapByInfoAndPolygonize) {
  write_zero_bomb(file("bomb.ply.gz"), 32);
  for (const std::string command : {"info bomb.ply.gz", "polygonize bomb.ply.gz -o out.obj"}) {
    const testing::CliRun r = run(command);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("bomb.ply.gz: gzip: the decompressed data exceeds"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("refusing what looks like a decompression bomb"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(file("out.obj")));
  EXPECT_TRUE(temporaries().empty());
}

// A 64 GiB mesh file (a hole, no disk): every command that reads a mesh runs out of memory
// reading it, and says so.
TEST_F(HostileInput, EveryCommandReportsRunningOutOfMemoryWhileReading) {
  sparse_file("huge.obj", uint64_t(64) << 30);
  expect_out_of_memory(run("info huge.obj"), "reading huge.obj: free memory");
  expect_out_of_memory(run("field --mesh huge.obj --radius 0.25", "0 0 0\n"), "reading huge.obj");
  expect_out_of_memory(run("slice huge.obj --radius 0.25 -o s.png"), "reading huge.obj");
  expect_out_of_memory(run("quick huge.obj --radius 0.25 --size 32x24 -o q.png"),
                       "reading huge.obj");
  expect_out_of_memory(run("polygonize huge.obj --radius 0.25 -o p.obj"), "reading huge.obj");
  expect_out_of_memory(run("distance " + kSoup + " huge.obj"), "reading huge.obj");
  // A scene's convolution mesh: the render names the scene it was parsing.
  std::ofstream(file("huge.pov")) << "camera { location <0, 0, -4> look_at 0 }\n"
                                     "convolution { radius 0.2 mesh { \"huge.obj\" } }\n";
  expect_out_of_memory(run("huge.pov +W32 +H24 -o r.png"), "parsing huge.pov");
  for (const std::string output : {"s.png", "q.png", "p.obj", "r.png"}) {
    EXPECT_FALSE(fs::exists(file(output))) << output;
  }
}

// Images and lattices whose estimate exceeds the cap are refused before any work, with the
// estimate and what to change; --force runs them into the out-of-memory message.
TEST_F(HostileInput, JobsThatCannotFitAreRefusedUnlessForced) {
  testing::CliRun r = run("quick " + kSoup + " --radius 0.25 --size 32768x32768 -o q.png");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("convray quick: a 32768x32768 image needs about"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("give a smaller --size, or --force to try anyway"), std::string::npos);

  r = run("slice " + kSoup + " --radius 0.25 --size 32768x32768 -o s.png");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("convray slice: a 32768x32768 image needs about"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("give a smaller --size, or --force to try anyway"), std::string::npos);

  r = run(kSoupScene + " +W32768 +H32768 -o r.png");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("convray: a 32768x32768 image needs about"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("give a smaller +W and +H, or --force"), std::string::npos);

  r = run(kSoupScene + " +W20000 +H20000 --force -o r.png");
  expect_out_of_memory(r, "rendering the 20000x20000 image");
  EXPECT_NE(r.err.find("give a smaller +W and +H"), std::string::npos);

  r = run("polygonize " + kSoup + " --radius 0.25 --cell 1e-4 -o p.obj");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("convray polygonize: polygonizing at cell 0.0001 needs about"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("lattice blocks"), std::string::npos);
  EXPECT_NE(r.err.find("give a larger --cell or --max-error, or --force to try anyway"),
            std::string::npos);

  // The bound no lattice can meet is refused after the first pass, not after eight.
  r = run("polygonize " + kSoup + " --radius 0.25 --max-error 1e-12 -o p.obj");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("the error bound needs a cell of about"), std::string::npos) << r.err;

  r = run("polygonize " + kSoup + " --radius 0.25 --cell 3e-4 --force -o p.obj");
  EXPECT_NE(r.err.find("polygonize: cell 0.0003: about"), std::string::npos) << r.err;
  expect_out_of_memory(r, "polygonizing: give a larger --cell or --max-error");
  for (const std::string output : {"q.png", "s.png", "r.png", "p.obj"}) {
    EXPECT_FALSE(fs::exists(file(output))) << output;
  }
}

// Ten million frames are planned in a few numbers, not a list (800 MB, past the cap): the run
// gets past planning to the scene, whose error it reports. --force skips the disk estimate.
TEST_F(HostileInput, TenMillionFramesArePlannedInBoundedMemory) {
  std::ofstream(file("broken.pov")) << "sphere { 0, 1 pigment { rgb 1 } \n";
  const testing::CliRun r = run("broken.pov +KFI1 +KFF9999999 +W32 +H24 --force -o f.png");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.find("out of memory"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("broken.pov:"), std::string::npos) << r.err;
}

// A number of bytes as byte_size writes it ("51.5 GB"), back to bytes.
double bytes_of(const std::string& text) {
  std::istringstream in(text);
  double value = 0;
  std::string unit;
  in >> value >> unit;
  const std::vector<std::string> units = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  const auto found = std::find(units.begin(), units.end(), unit);
  return value * std::pow(1000.0, double(found - units.begin()));
}

// Frames that cannot fit on the disk are refused before the first, with the space they may
// need (each frame uncompressed: 2000 x 3 bytes + a filter byte per row, 2000 rows, 4 KiB of
// headers) and the space free, which df reports too; --force skips the estimate.
TEST_F(HostileInput, AnAnimationThatCannotFitOnTheDiskIsRefusedBeforeAnyFrame) {
  const testing::CliRun r = run(kSoupScene + " +KFI1 +KFF9999999 +W2000 +H2000 -o f.png");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const std::string start = "convray: the 9999999 frames of 2000x2000 may need up to ";
  ASSERT_EQ(r.err.rfind(start, 0), 0u) << r.err;
  const double per_frame = (2000.0 * 3 + 1) * 2000 + 4096;
  EXPECT_NEAR(bytes_of(r.err.substr(start.size())), 9999999 * per_frame,
              0.001 * 9999999 * per_frame);
  EXPECT_NE(r.err.find("on disk (12 MB a frame, uncompressed)"), std::string::npos) << r.err;
  const size_t free_at = r.err.find("more than the ");
  ASSERT_NE(free_at, std::string::npos) << r.err;
  // df's figure for the same folder, in bytes available to this user.
  ASSERT_EQ(std::system(("df -B1 --output=avail '" + dir_.string() + "' | tail -1 > '" +
                         file("df.txt") + "'")
                            .c_str()),
            0);
  const double df_free = std::stod(testing::read_file(file("df.txt")));
  EXPECT_NEAR(bytes_of(r.err.substr(free_at + 14)), df_free, 0.01 * df_free + 1e7) << r.err;
  EXPECT_NE(r.err.find("give fewer frames (+KFI, +KFF, +SF, +EF, Frame_Step), a smaller +W and "
                       "+H or another output folder, or --force to try anyway"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(file("f0000001.png")));
}

// Points without a line break: refused at the line instead of read into memory whole.
TEST_F(HostileInput, FieldRefusesALineLongerThan4096Characters) {
  const testing::CliRun r = run("field --mesh " + kSoup + " --radius 0.25",
                                "0 0 0\n" + std::string(1 << 20, '1'));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err, "stdin:2: the line is longer than 4096 characters\n");
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;  // the first point's answer
}

// One triangle a million times: merged into one with multiplicity 10^6, so the field, the
// lattice and the mesh are those of the single triangle with 10^6 times its strength (an
// independent route to the same sum), within the cap.
TEST_F(HostileInput, AMillionCopiesOfOneTriangleCostOne) {
  const std::string corners = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  {
    std::ofstream many(file("many.obj"));
    many << corners;
    for (int k = 0; k < 1000000; ++k) many << "f 1 2 3\n";
    std::ofstream(file("one.obj")) << corners << "f 1 2 3\n";
  }
  const std::string points = "0.2 0.2 0.05\n0.5 0.1 -0.1\n1.1 0.2 0.1\n";
  const testing::CliRun many = run("field --mesh many.obj --radius 0.3", points);
  const testing::CliRun one = run("field --mesh one.obj --radius 0.3 --strength 1e6", points);
  ASSERT_EQ(many.exit_code, 0) << many.err;
  ASSERT_EQ(one.exit_code, 0) << one.err;
  std::istringstream a(many.out), b(one.out);
  double x = 0.0, y = 0.0;
  int values = 0;
  while (a >> x && b >> y) {
    EXPECT_NEAR(x, y, 1e-9 * (1.0 + std::abs(y))) << values;
    ++values;
  }
  EXPECT_EQ(values, 12);

  // Polygonized at one threshold, the two fields being equal, the meshes are too.
  const testing::CliRun single =
      run("polygonize one.obj --radius 0.3 --strength 1e6 --threshold 2e4 --cell 0.02 -o one.ply");
  const testing::CliRun copies =
      run("polygonize many.obj --radius 0.3 --threshold 2e4 --cell 0.02 -o many.ply");
  ASSERT_EQ(single.exit_code, 0) << single.err;
  ASSERT_EQ(copies.exit_code, 0) << copies.err;
  // The report's first line: triangle and vertex counts and the cell.
  EXPECT_EQ(single.out.substr(0, single.out.find('\n')),
            copies.out.substr(0, copies.out.find('\n')));
}

}  // namespace
}  // namespace convray
