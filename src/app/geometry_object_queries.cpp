#include "app/geometry_object_queries.hpp"

#include "geometry/world.hpp"
#include "scene/object.hpp"

namespace convray::app {

namespace {

constexpr double kHuge = 1e10;

class GeometryQueries final : public sdl::ObjectQueries {
 public:
  // As POV-Ray reports them: an object without extent (a text of spaces) at <0, 0, 0>, and
  // unbounded sides (planes, inverse) at +-1e10.
  Box3 bounds(const scene::Object& object) const override {
    Box3 box = geometry::build_shape(object)->bounds();
    if (box.empty()) return Box3{Vec3(0.0), Vec3(0.0)};
    box.lo = glm::clamp(box.lo, Vec3(-kHuge), Vec3(kHuge));
    box.hi = glm::clamp(box.hi, Vec3(-kHuge), Vec3(kHuge));
    return box;
  }

  std::optional<sdl::TraceHit> trace(const scene::Object& object, const Vec3& origin,
                                     const Vec3& direction) const override {
    const geometry::ShapePtr shape = geometry::build_shape(object);
    const Ray ray{origin, glm::normalize(direction)};
    TraceStats stats;
    const auto crossing = shape->first_crossing(ray, 0.0, INFINITY, stats);
    if (!crossing) return std::nullopt;
    return sdl::TraceHit{ray.at(crossing->t), crossing->normal};
  }
};

}  // namespace

std::shared_ptr<const sdl::ObjectQueries> geometry_object_queries() {
  static const auto queries = std::make_shared<const GeometryQueries>();
  return queries;
}

}  // namespace convray::app
