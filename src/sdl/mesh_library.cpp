#include "sdl/mesh_library.hpp"

#include <filesystem>

#include "mesh/load.hpp"

namespace convray::sdl {

SharedTriangles MeshLibrary::read(const std::string& path) {
  const mesh::LoadedMesh loaded = mesh::load_mesh(path);
  mesh::require_triangles(loaded, path, "a convolution mesh");
  auto triangles = std::make_shared<std::vector<field::Triangle>>();
  triangles->reserve(loaded.soup.size());
  for (size_t t = 0; t < loaded.soup.size(); ++t) {
    const auto corners = loaded.soup.corners(t);
    triangles->push_back({corners[0], corners[1], corners[2]});
  }
  return triangles;
}

SharedTriangles MeshLibrary::load(const std::string& path) {
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
      return it->second.triangles;
    }
  }
  // Read outside the lock: other files may be read meanwhile (the same one, at worst, twice).
  SharedTriangles triangles = read(path);
  std::lock_guard lock(mutex_);
  ++reads_;
  entries_[path] = Entry{size, ticks, triangles};
  return triangles;
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
