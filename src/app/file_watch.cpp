#include "app/file_watch.hpp"

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
  files_ = files;
  seen_.clear();
  for (const std::string& f : files_) seen_.push_back(look(f));
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
