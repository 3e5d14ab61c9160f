#pragma once
// Acceleration structures of mesh components, kept from one ConvolutionSurface to the next:
// an animation re-reads its scene every frame, but a mesh component with the same file (its
// MeshSource::local, shared through sdl::MeshLibrary) and the same radius needs the same
// hierarchy over its supports. Rigid placements of one file share one hierarchy in the file's
// own space, placed as an Embree instance; other placements (scales) get a hierarchy over the
// placed triangles, kept under the exact placement. Frames call next_frame() so that what the
// last frame did not use is dropped (a mesh scaled differently every frame costs one build per
// frame, not one hierarchy per frame forever).
//
// Thread-safe: surfaces may be built on several threads; a hierarchy wanted by two of them
// at once is built once (the second waits for it).
#include <memory>
#include <span>

#include "scene/convolution_object.hpp"

namespace convray::accel {
class TriangleSupports;
}

namespace convray::implicit {

class SupportCache {
 public:
  struct Counts {
    size_t builds = 0;  // hierarchies built
    size_t reuses = 0;  // requests answered with a hierarchy built before
  };

  SupportCache();
  ~SupportCache();
  SupportCache(const SupportCache&) = delete;
  SupportCache& operator=(const SupportCache&) = delete;

  Counts counts() const;
  size_t size() const;          // hierarchies held
  size_t memory_bytes() const;  // what they hold (Embree's allocations)
  // Ends a frame: drops the hierarchies not asked for since the previous call.
  void next_frame();

  // For ConvolutionSurface: a hierarchy over the supports (radius `radius`) of the component
  // whose object-space triangles are `triangles`, placed from `source`, and the placement that
  // carries it onto them; its margin suits an index whose supports span `index_bounds`.
  struct Placed {
    std::shared_ptr<const accel::TriangleSupports> supports;
    Mat4 placement{1.0};
  };
  Placed acquire(const scene::MeshSource& source, std::span<const field::Triangle> triangles,
                 double radius, const Box3& index_bounds);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace convray::implicit
