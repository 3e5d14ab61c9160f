#pragma once
// Mesh files read once per animation: the parser asks the library for a convolution mesh's
// skeleton (triangles, segments, points); the same file (resolved path, size and modification
// time alike) gives the same shared skeleton, whose triangles later stages recognise
// (scene::MeshSource, SupportCache). A file that changed on disk is read again. Thread-safe.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "scene/mesh_skeleton.hpp"

namespace convray::sdl {

using SharedSkeleton = std::shared_ptr<const scene::MeshSkeleton>;

class MeshLibrary {
 public:
  // The skeleton of the mesh file at `path` (resolved already): read now, or kept from an
  // earlier call when the file's size and modification time are unchanged. Throws what
  // mesh::load_mesh throws.
  SharedSkeleton load(const std::string& path);
  // Reads the file, keeping nothing.
  static SharedSkeleton read(const std::string& path);

  size_t reads() const;  // files read (not answered from the library)
  size_t size() const;   // files kept

 private:
  struct Entry {
    uintmax_t size = 0;
    int64_t modified = 0;  // the file clock's ticks
    SharedSkeleton skeleton;
  };
  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;
  size_t reads_ = 0;
};

}  // namespace convray::sdl
