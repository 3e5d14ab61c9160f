#pragma once
// Private to src/accel: what a TriangleSupports holds, for SupportIndex to place it.
#include "accel/support_geometry.hpp"
#include "accel/triangle_supports.hpp"

namespace convray::accel {

struct TriangleSupports::Impl {
  std::shared_ptr<const std::vector<field::Triangle>> triangles;
  detail::GeometrySource source;  // geomID 0 of `scene`, in the triangles' space
  RTCSceneTy* scene = nullptr;
  Box3 bounds;
  long long bytes = 0;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() { detail::release_scene(scene); }
};

}  // namespace convray::accel
