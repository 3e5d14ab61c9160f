#include "sdl/mesh_library.hpp"

#include <filesystem>

#include "mesh/load.hpp"

namespace convray::sdl {

SharedSkeleton MeshLibrary::read(const std::string& path) {
  return std::make_shared<const scene::MeshSkeleton>(scene::skeleton_of(mesh::load_mesh(path)));
}

SharedSkeleton MeshLibrary::load(const std::string& path) {
  // Stamped before reading: a file rewritten while it is read is read again next time.
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(path, error);
  const auto modified = std::filesystem::last_write_time(path, error);
  if (error) return read(path);  // let the reader report what is wrong with it
  const int64_t ticks = int64_t(modified.time_since_epoch().count());
  {
    std::lock_guard lock(mutex_);
    const auto it = entries_.find(path);
    if (it != entries_.end() && it->second.size == size && it->second.modified == ticks) {
      return it->second.skeleton;
    }
  }
  // Read outside the lock: other files may be read meanwhile (the same one, at worst, twice).
  SharedSkeleton skeleton = read(path);
  std::lock_guard lock(mutex_);
  ++reads_;
  entries_[path] = Entry{size, ticks, skeleton};
  return skeleton;
}

size_t MeshLibrary::reads() const {
  std::lock_guard lock(mutex_);
  return reads_;
}

size_t MeshLibrary::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

}  // namespace convray::sdl
