#pragma once
// What the scene language asks of its objects that only their geometry can answer:
// min_extent / max_extent (an object's bounding box) and trace (where a ray first meets it).
// The language does not know about shapes or rays; the program (app/) hands the parser an
// implementation that builds the object's shape (ParseOptions::object_queries).
#include <optional>

#include "util/math.hpp"

namespace convray::scene {
struct Object;
}

namespace convray::sdl {

struct TraceHit {
  Vec3 point{0.0};
  Vec3 normal{0.0};  // unit, pointing out of the object
};

class ObjectQueries {
 public:
  virtual ~ObjectQueries() = default;
  // The box around the object as placed (its transform applied).
  virtual Box3 bounds(const scene::Object& object) const = 0;
  // The first point where the ray origin + t direction (t > 0) meets the object's surface.
  virtual std::optional<TraceHit> trace(const scene::Object& object, const Vec3& origin,
                                        const Vec3& direction) const = 0;
};

}  // namespace convray::sdl
