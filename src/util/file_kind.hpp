#pragma once
// What a path names when it is not a file that can be read whole: a folder, a named pipe, a
// device, a socket, a loop of symbolic links. Readers ask before they open: a named pipe waits
// for a writer and /dev/zero never ends, and "file not found" would name the wrong problem.
#include <filesystem>
#include <optional>
#include <string>

namespace convray {

// "a folder", "a named pipe", "a character device", ...: for a status that is not a regular
// file.
std::string describe_file_kind(const std::filesystem::file_status& status);

// Why `path` cannot be read as a file, as a phrase to follow it ("is a named pipe, not a
// file", "is a loop of symbolic links"), or nothing when it is a regular file (links
// followed) or does not exist (which opening it reports).
std::optional<std::string> not_a_file(const std::string& path);

}  // namespace convray
