#include "app/frame_names.hpp"

#include <filesystem>

namespace convray::app {
namespace {

namespace fs = std::filesystem;

// The name split around the place where the frame number goes: before the extension.
std::pair<std::string, std::string> split_at_extension(const std::string& name) {
  const fs::path path(name);
  const std::string extension = path.extension().string();
  return {name.substr(0, name.size() - extension.size()), extension};
}

}  // namespace

bool names_folder(const std::string& output) {
  if (output.empty()) return false;
  if (output.back() == '/') return true;
  std::error_code error;
  return fs::is_directory(output, error);
}

std::string resolve_output(const std::string& output, const std::string& scene) {
  const fs::path own_name = fs::path(scene).filename().replace_extension(".png");
  if (output.empty()) return own_name.string();
  if (names_folder(output)) return (fs::path(output) / own_name).string();
  if (!fs::path(output).has_extension()) return output + ".png";
  return output;
}

std::string frame_file_name(const std::string& still_name, long long frame, int digits) {
  std::string number = std::to_string(frame);
  if (int(number.size()) < digits) number.insert(0, size_t(digits) - number.size(), '0');
  const auto [stem, extension] = split_at_extension(still_name);
  return stem + number + extension;
}

}  // namespace convray::app
