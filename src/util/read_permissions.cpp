#include "util/read_permissions.hpp"

#include <algorithm>
#include <filesystem>

namespace convray {

namespace fs = std::filesystem;

namespace {

std::string without_trailing_separator(std::string text) {
  while (text.size() > 1 && text.back() == '/') text.pop_back();
  return text;
}

void add_once(std::vector<std::string>& list, std::string folder) {
  if (std::find(list.begin(), list.end(), folder) == list.end()) list.push_back(std::move(folder));
}

bool lies_in_one_of(const std::string& path, const std::vector<std::string>& folders) {
  return std::any_of(folders.begin(), folders.end(), [&](const std::string& folder) {
    if (folder == "/") return true;
    return path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 &&
           path[folder.size()] == '/';
  });
}

}  // namespace

void ReadPermissions::allow(const std::string& folder) {
  std::error_code error;
  const fs::path resolved = fs::canonical(folder.empty() ? fs::path(".") : fs::path(folder), error);
  if (error || !fs::is_directory(resolved, error)) return;
  add_once(folders_, without_trailing_separator(resolved.string()));
}

void ReadPermissions::allow_with_links(const std::string& folder) {
  allow(folder);
  std::error_code error;
  const fs::path absolute = fs::absolute(fs::path(folder), error).lexically_normal();
  if (error || !fs::is_directory(absolute, error)) return;
  add_once(trusted_, without_trailing_separator(absolute.string()));
}

bool ReadPermissions::allows(const std::string& path) const {
  if (anywhere_) return true;
  std::error_code error;
  const std::string by_name = fs::absolute(fs::path(path), error).lexically_normal().string();
  if (!error && lies_in_one_of(by_name, trusted_)) return true;
  const std::string resolved = fs::canonical(path, error).string();
  return !error && lies_in_one_of(resolved, folders_);
}

}  // namespace convray
