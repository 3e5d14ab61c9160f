// util::AtomicFile and its temporaries, in this process and in forked children: a write that
// fails (a file-size limit standing in for a full disk) leaves the previous file as it was,
// symlinks are never followed, and temporaries of dead owners are cleaned, of live ones kept.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "reference/test_folder.hpp"
#include "app/cli.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "util/partial_files.hpp"

namespace convray {
namespace {

namespace fs = std::filesystem;

using testing::read_file;

std::string read_all(const fs::path& path) { return read_file(path); }

class AtomicFileTest : public ::testing::Test {
 protected:
  // Every name in the folder, sorted: temporaries included (they start with a dot).
  std::vector<std::string> names() const {
    std::vector<std::string> all;
    for (const auto& entry : fs::directory_iterator(dir_)) all.push_back(entry.path().filename());
    std::sort(all.begin(), all.end());
    return all;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  convray::testing::TestFolder folder_{"atomic"};
  const fs::path& dir_ = folder_.path();
};

// A process id that is certainly free: a child that has exited and been reaped.
pid_t dead_process_id() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST_F(AtomicFileTest, WritesTheWholeFileAndNothingElse) {
  write_file_atomically(path("out.txt"), "hello", "the text");
  EXPECT_EQ(read_all(path("out.txt")), "hello");
  EXPECT_EQ(names(), std::vector<std::string>{"out.txt"});
}

TEST_F(AtomicFileTest, AnUncommittedFileLeavesThePreviousOne) {
  std::ofstream(path("out.txt")) << "good";
  {
    AtomicFile file(path("out.txt"), "the text");
    file.write("half of a new fi");
  }  // destroyed without commit: an exception or a return half-way
  EXPECT_EQ(read_all(path("out.txt")), "good");
  EXPECT_EQ(names(), std::vector<std::string>{"out.txt"});
}

TEST_F(AtomicFileTest, AFullDiskLeavesThePreviousFileAndReportsIt) {
  std::ofstream(path("keep.bin")) << "the user's good file";
  // In a child: RLIMIT_FSIZE makes write() fail with EFBIG past 4 KiB, as a full disk fails it
  // with ENOSPC; SIGXFSZ ignored so that the write reports instead of killing.
  const pid_t child = ::fork();
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      write_file_atomically(path("keep.bin"), std::string(100000, 'x'), "the data");
      ::_exit(0);
    } catch (const InputError& e) {
      const std::string text = e.what();
      ::_exit(text.find("keep.bin: cannot write the data: File too large") != std::string::npos
                  ? 42
                  : 1);
    }
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 42);
  EXPECT_EQ(read_all(path("keep.bin")), "the user's good file");
  EXPECT_EQ(names(), std::vector<std::string>{"keep.bin"});
}

TEST_F(AtomicFileTest, ASymlinkAtTheDestinationIsReplacedNotFollowed) {
  std::ofstream(path("victim.txt")) << "secret";
  fs::create_symlink(path("victim.txt"), path("x.png"));
  write_file_atomically(path("x.png"), "picture", "the image");
  EXPECT_EQ(read_all(path("victim.txt")), "secret");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(path("x.png"))));
  EXPECT_EQ(read_all(path("x.png")), "picture");
}

TEST_F(AtomicFileTest, TemporaryNamesAreFreshAndNeverReused) {
  std::set<std::string> seen;
  for (int i = 0; i < 1000; ++i) seen.insert(partial_name_for(path("a.png")).string());
  EXPECT_EQ(seen.size(), 1000u);
  // A symlink planted at a predictable name (the fixed `.a.partial.png` of earlier versions)
  // is not where anything is written: the victim stays as it was.
  std::ofstream(path("victim.txt")) << "secret";
  fs::create_symlink(path("victim.txt"), path(".a.partial.png"));
  for (int i = 0; i < 20; ++i) {
    write_file_atomically(path("a.png"), "round " + std::to_string(i), "the image");
  }
  EXPECT_EQ(read_all(path("victim.txt")), "secret");
  EXPECT_EQ(read_all(path("a.png")), "round 19");
}

TEST_F(AtomicFileTest, DevicesFoldersAndMissingFoldersAreRefusedBeforeWriting) {
  EXPECT_THROW(check_writable_destination("/dev/full", "the image"), InputError);
  EXPECT_THROW(check_writable_destination("/dev/null", "the image"), InputError);
  fs::create_directory(path("folder"));
  EXPECT_THROW(check_writable_destination(path("folder"), "the image"), InputError);
  EXPECT_THROW(check_writable_destination(path("none/a.png"), "the image"), InputError);
  EXPECT_NO_THROW(check_writable_destination(path("new.png"), "the image"));
  try {
    check_writable_destination("/dev/full", "the image");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("character device"), std::string::npos) << e.what();
  }
}

TEST_F(AtomicFileTest, OrphanedTemporariesOfDeadOwnersGoAndOthersStay) {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::string here(host);
  const pid_t dead = dead_process_id();
  const std::string dead_name = ".a.png.convray." + here + "." + std::to_string(dead) + ".0a1b2c3d.partial";
  const std::string dead_folder = ".a.png.convray." + here + "." + std::to_string(dead) + ".0f0f0f0f.partial.d";
  const std::string live_name = ".a.png.convray." + here + "." + std::to_string(::getppid()) + ".11111111.partial";
  const std::string other_host = ".a.png.convray.elsewhere." + std::to_string(dead) + ".22222222.partial";
  const std::string other_file = ".b.png.convray." + here + "." + std::to_string(dead) + ".33333333.partial";
  for (const std::string& name : {dead_name, live_name, other_host, other_file}) {
    std::ofstream(path(name)) << "x";
  }
  fs::create_directory(path(dead_folder));
  std::ofstream(path(dead_folder + "/video.mp4")) << "x";

  EXPECT_TRUE(is_orphaned_partial(path("a.png"), dead_name));
  EXPECT_FALSE(is_orphaned_partial(path("a.png"), live_name));
  EXPECT_FALSE(is_orphaned_partial(path("a.png"), other_host));
  EXPECT_FALSE(is_orphaned_partial(path("a.png"), other_file));
  EXPECT_FALSE(is_orphaned_partial(path("a.png"), "a.png"));

  write_file_atomically(path("a.png"), "new", "the image");
  std::vector<std::string> expected = {live_name, other_host, other_file, "a.png"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names(), expected);
}

TEST_F(AtomicFileTest, ByNameWritersGetAPrivateFolderThatAlwaysGoes) {
  std::ofstream(path("v.mp4")) << "old video";
  {
    AtomicFileByName file(path("v.mp4"), "the video", "video.mp4");
    EXPECT_EQ((fs::status(file.path().parent_path()).permissions() & fs::perms::all),
              fs::perms::owner_all);
    std::ofstream(file.path()) << "";  // the writer failed and left an empty file
    EXPECT_THROW(file.commit(), InputError);
  }
  EXPECT_EQ(read_all(path("v.mp4")), "old video");
  EXPECT_EQ(names(), std::vector<std::string>{"v.mp4"});
  {
    AtomicFileByName file(path("v.mp4"), "the video", "video.mp4");
    std::ofstream(file.path()) << "new video";
    file.commit();
  }
  EXPECT_EQ(read_all(path("v.mp4")), "new video");
  EXPECT_EQ(names(), std::vector<std::string>{"v.mp4"});
}

TEST_F(AtomicFileTest, ATerminatingSignalRemovesTheTemporary) {
  std::ofstream(path("keep.bin")) << "good";
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    AtomicFile file(path("keep.bin"), "the data");
    file.write("partly written");
    (void)!::write(ready[1], "r", 1);
    ::pause();  // killed here, mid-write
    ::_exit(0);
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  EXPECT_EQ(names().size(), 2u);  // keep.bin and the child's temporary
  ::kill(child, SIGTERM);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_EQ(names(), std::vector<std::string>{"keep.bin"});
  EXPECT_EQ(read_all(path("keep.bin")), "good");
  ::close(ready[0]);
  ::close(ready[1]);
}

}  // namespace
}  // namespace convray
