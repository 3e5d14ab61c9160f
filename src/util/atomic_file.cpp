#include "util/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "util/error.hpp"
#include "util/partial_files.hpp"

namespace convray {

namespace fs = std::filesystem;

namespace {

std::string describe_kind(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a named pipe";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

fs::path folder_of(const fs::path& destination) {
  return destination.parent_path().empty() ? fs::path(".") : destination.parent_path();
}

// Makes the rename itself survive a power cut. Best effort: some file systems refuse to
// sync a folder, which only weakens that guarantee.
void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// The mode a new file gets: the replaced file's, if there is one of ours, else 0666 & ~umask.
void copy_mode_of_replaced(int fd, const fs::path& destination) {
  struct stat info {};
  if (::stat(destination.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
      info.st_uid == ::getuid()) {
    ::fchmod(fd, info.st_mode & 07777);
  }
}

}  // namespace

void check_writable_destination(const std::string& destination, const std::string& what) {
  const fs::path path(destination);
  const fs::path folder = folder_of(path);
  struct stat info {};
  if (::stat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) {
    throw InputError({destination}, "cannot write " + what + ": folder '" + folder.string() +
                                        "' does not exist");
  }
  if (::stat(path.c_str(), &info) != 0) return;  // a new file
  if (S_ISDIR(info.st_mode)) {
    throw InputError({destination}, "cannot write " + what + ": a folder of that name exists");
  }
  if (!S_ISREG(info.st_mode)) {
    throw InputError({destination}, "cannot write " + what + ": it is " +
                                        describe_kind(info.st_mode) +
                                        "; convray writes only regular files");
  }
}

// --- AtomicFile ---------------------------------------------------------------------------

AtomicFile::AtomicFile(std::string destination, std::string what)
    : destination_(std::move(destination)), what_(std::move(what)) {
  check_writable_destination(destination_, what_);
  remove_orphaned_partials(destination_);
  for (int attempt = 0; attempt < 16 && fd_ < 0; ++attempt) {
    temporary_ = partial_name_for(destination_);
    fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0 && errno != EEXIST) break;
  }
  if (fd_ < 0) {
    const int error = errno;
    temporary_.clear();
    throw InputError({destination_}, "cannot write " + what_ + ": " + std::strerror(error));
  }
  register_partial(temporary_);
  copy_mode_of_replaced(fd_, destination_);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temporary_.empty()) {
    ::unlink(temporary_.c_str());
    unregister_partial(temporary_);
  }
}

void AtomicFile::fail(const std::string& reason) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(temporary_.c_str());
  unregister_partial(temporary_);
  temporary_.clear();
  throw InputError({destination_}, "cannot write " + what_ + ": " + reason);
}

void AtomicFile::write(std::string_view bytes) {
  if (fd_ < 0) fail("the file is already closed");
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(n < 0 ? std::strerror(errno) : "the disk took no bytes");
    bytes.remove_prefix(size_t(n));
  }
}

void AtomicFile::commit() {
  if (fd_ < 0 || committed_) fail("the file is already closed");
  if (::fsync(fd_) != 0 && errno != EINVAL) fail(std::strerror(errno));
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail(std::strerror(errno));
  if (::rename(temporary_.c_str(), destination_.c_str()) != 0) fail(std::strerror(errno));
  committed_ = true;
  unregister_partial(temporary_);
  sync_folder(folder_of(destination_));
}

void write_file_atomically(const std::string& destination, std::string_view bytes,
                           const std::string& what) {
  AtomicFile file(destination, what);
  file.write(bytes);
  file.commit();
}

// --- AtomicFileByName ---------------------------------------------------------------------

AtomicFileByName::AtomicFileByName(std::string destination, std::string what,
                                   const std::string& inner_name)
    : destination_(std::move(destination)), what_(std::move(what)) {
  check_writable_destination(destination_, what_);
  remove_orphaned_partials(destination_);
  bool made = false;
  for (int attempt = 0; attempt < 16 && !made; ++attempt) {
    folder_ = partial_name_for(destination_, ".partial.d");
    made = ::mkdir(folder_.c_str(), 0700) == 0;
    if (!made && errno != EEXIST) break;
  }
  if (!made) {
    const int error = errno;
    folder_.clear();
    throw InputError({destination_}, "cannot write " + what_ + ": " + std::strerror(error));
  }
  register_partial(folder_);
  inner_ = folder_ / inner_name;
  register_partial(inner_);
}

AtomicFileByName::~AtomicFileByName() {
  std::error_code ignored;
  if (!folder_.empty()) fs::remove_all(folder_, ignored);
  unregister_partial(inner_);
  unregister_partial(folder_);
}

void AtomicFileByName::commit() {
  struct stat info {};
  if (::lstat(inner_.c_str(), &info) != 0 || !S_ISREG(info.st_mode) || info.st_size == 0) {
    throw InputError({destination_}, "cannot write " + what_ + ": the writer left no file");
  }
  const int fd = ::open(inner_.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  const bool synced = fd >= 0 && (::fsync(fd) == 0 || errno == EINVAL);
  const int sync_error = errno;
  if (fd >= 0) ::close(fd);
  if (!synced) {
    throw InputError({destination_}, "cannot write " + what_ + ": " + std::strerror(sync_error));
  }
  if (::rename(inner_.c_str(), destination_.c_str()) != 0) {
    throw InputError({destination_}, "cannot write " + what_ + ": " + std::strerror(errno));
  }
  committed_ = true;
  sync_folder(folder_of(fs::path(destination_)));
}

}  // namespace convray
