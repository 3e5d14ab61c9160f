#include "app/file_watch.hpp"

#include <algorithm>

namespace convray::app {

FileWatch::Seen FileWatch::look(const std::string& file) {
  std::error_code error;
  Seen seen;
  seen.time = std::filesystem::last_write_time(file, error);
  if (error) return {};
  seen.size = std::filesystem::file_size(file, error);
  if (error) return {};
  seen.exists = true;
  return seen;
}

void FileWatch::watch(const std::vector<std::string>& files) {
  if (files == files_) return;  // the same list: its reference state stands
  // A file watched before keeps its reference: a save that came after the parse that changed
  // the list (an editor's truncation parsed, then its write) is still seen.
  std::vector<Seen> seen;
  for (const std::string& f : files) {
    const auto known = std::find(files_.begin(), files_.end(), f);
    seen.push_back(known != files_.end() ? seen_[size_t(known - files_.begin())] : look(f));
  }
  files_ = files;
  seen_ = std::move(seen);
}

bool FileWatch::changed() {
  bool any = false;
  for (size_t i = 0; i < files_.size(); ++i) {
    const Seen now = look(files_[i]);
    if (!(now == seen_[i])) any = true, seen_[i] = now;
  }
  return any;
}

}  // namespace convray::app
