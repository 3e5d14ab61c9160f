#include "accel/triangle_supports.hpp"

#include <stdexcept>

#include "accel/support_shapes.hpp"
#include "accel/triangle_supports_impl.hpp"

namespace convray::accel {

Box3 triangle_supports_bounds(std::span<const field::Triangle> triangles, double radius) {
  Box3 bounds;
  for (const field::Triangle& t : triangles) {
    const Box3 box = triangle_support_box(t, radius);
    bounds.extend(box.lo);
    bounds.extend(box.hi);
  }
  return bounds;
}

TriangleSupports::TriangleSupports(std::shared_ptr<const std::vector<field::Triangle>> triangles,
                                   double radius, double margin)
    : impl_(std::make_unique<Impl>()) {
  if (!triangles) throw std::invalid_argument("TriangleSupports: no triangles");
  if (!(radius > 0.0) || !(margin >= 0.0)) {
    throw std::invalid_argument("TriangleSupports: radius must be positive, margin not negative");
  }
  Impl& m = *impl_;
  m.triangles = std::move(triangles);
  m.bounds = triangle_supports_bounds(*m.triangles, radius);
  using Kind = detail::GeometrySource::Kind;
  m.source = detail::GeometrySource{Kind::triangle};
  m.source.count = uint32_t(m.triangles->size());
  m.source.triangles = m.triangles->data();
  m.source.shared_radius = radius;
  m.source.margin = margin;
  detail::SceneBuild build;
  if (m.source.count > 0) build.add_user_geometry(m.source);
  m.scene = build.commit("building a mesh's support hierarchy");
  m.bytes = build.bytes();
}

TriangleSupports::~TriangleSupports() = default;

const std::vector<field::Triangle>& TriangleSupports::triangles() const {
  return *impl_->triangles;
}
size_t TriangleSupports::size() const { return impl_->triangles->size(); }
double TriangleSupports::radius() const { return impl_->source.shared_radius; }
double TriangleSupports::margin() const { return impl_->source.margin; }
Box3 TriangleSupports::bounds() const { return impl_->bounds; }
size_t TriangleSupports::memory_bytes() const { return size_t(impl_->bytes); }

}  // namespace convray::accel
