#pragma once
// The one way convray writes a file (images, animation frames, meshes, videos, frame lists):
// it appears whole or not at all, and the file it replaces survives any failure.
//
//   1. The destination is checked: its folder exists, and it is not a folder, a device or a
//      pipe (`-o /dev/full` is refused rather than written beside).
//   2. A fresh temporary is created beside it (util/partial_files.hpp names it) with
//      O_CREAT|O_EXCL|O_NOFOLLOW, so two processes writing one name never share a file and a
//      symlink planted at a temporary's name is never followed.
//   3. Every write, the fsync and the close are checked; then the temporary is renamed over
//      the destination (atomic within a file system) and the folder is synced.
//   4. Any failure removes the temporary, leaves the previous file untouched, and throws
//      InputError("DEST: cannot write <what>: <reason>"), e.g. "No space left on device".
// Of two processes writing one name, the last rename wins, always with a complete file.
#include <filesystem>
#include <string>
#include <string_view>

namespace convray {

// Checks step 1 before any work is done; throws InputError naming `what` ("the image").
void check_writable_destination(const std::string& destination, const std::string& what);

class AtomicFile {
 public:
  // Steps 1 and 2; also removes the orphaned temporaries of earlier, killed runs.
  AtomicFile(std::string destination, std::string what);
  ~AtomicFile();  // without commit(): the temporary is removed, the destination untouched
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view bytes);  // all of them, or InputError
  void commit();                       // step 3; once

  const std::string& destination() const { return destination_; }

 private:
  [[noreturn]] void fail(const std::string& reason);

  std::string destination_, what_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  bool committed_ = false;
};

// The whole file at once.
void write_file_atomically(const std::string& destination, std::string_view bytes,
                           const std::string& what);

// For writers that open their file by name (another program, a library): they write
// `path()`, inside a private folder (mode 0700) beside the destination that no one else can
// plant anything in; commit() checks it is a regular, non-empty file, syncs it and renames it
// over the destination. The folder goes in every case.
class AtomicFileByName {
 public:
  AtomicFileByName(std::string destination, std::string what, const std::string& inner_name);
  ~AtomicFileByName();
  AtomicFileByName(const AtomicFileByName&) = delete;
  AtomicFileByName& operator=(const AtomicFileByName&) = delete;

  const std::filesystem::path& path() const { return inner_; }
  void commit();

 private:
  std::string destination_, what_;
  std::filesystem::path folder_, inner_;
  bool committed_ = false;
};

}  // namespace convray
