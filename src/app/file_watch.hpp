#pragma once
// The files a scene read, watched by polling: `convray view` asks a few times a second
// whether any was saved since (its modification time or size changed, it appeared or went).
// Polling needs nothing from the system and sees editors that save by renaming a new file
// over the old, which an inotify watch on the old file would miss.
#include <filesystem>
#include <string>
#include <vector>

namespace convray::app {

class FileWatch {
 public:
  // Watches `files` from now on: their state now is the reference, but for files watched
  // already, which keep theirs.
  void watch(const std::vector<std::string>& files);
  // Whether a watched file changed since watch() or the last call that said so; the new
  // state becomes the reference.
  bool changed();
  const std::vector<std::string>& files() const { return files_; }

 private:
  struct Seen {
    bool exists = false;
    std::filesystem::file_time_type time{};
    std::uintmax_t size = 0;
    bool operator==(const Seen&) const = default;
  };
  static Seen look(const std::string& file);

  std::vector<std::string> files_;
  std::vector<Seen> seen_;
};

}  // namespace convray::app
