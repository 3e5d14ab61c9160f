#include "util/file_kind.hpp"

#include <cerrno>

namespace convray {

namespace fs = std::filesystem;

std::string describe_file_kind(const fs::file_status& status) {
  switch (status.type()) {
    case fs::file_type::directory: return "a folder";
    case fs::file_type::fifo: return "a named pipe";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

std::optional<std::string> not_a_file(const std::string& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error.value() == ELOOP) return "is a loop of symbolic links";
  if (!fs::exists(status) || fs::is_regular_file(status)) return std::nullopt;
  return "is " + describe_file_kind(status) + ", not a file";
}

}  // namespace convray
