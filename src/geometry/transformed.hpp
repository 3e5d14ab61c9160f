#pragma once
// An object placed by its transform: rays go into the object's own space (direction
// renormalised, distances scaled back), normals come out by the inverse transpose.
//
// Also a placement of a declared union whose members are shared by every placement
// (geometry/instance.hpp): the child is then shared, and crossings name the placement
// (Crossing::texture_space), since the shared members' textures are in the union's own space.
#include <memory>

#include "geometry/shape.hpp"
#include "scene/transform.hpp"

namespace convray::geometry {

class TransformedShape final : public Shape {
 public:
  // `transform` maps the child's space to this shape's; it must be invertible.
  // `places_shared`: the child is a shared union's members (see above).
  TransformedShape(std::shared_ptr<const Shape> child, const scene::Transform& transform,
                   bool places_shared = false);

  Box3 bounds() const override;
  void crossings(const Ray& ray, double tmin, double tmax, std::vector<Crossing>& out,
                 TraceStats& stats) const override;
  std::optional<Crossing> first_crossing(const Ray& ray, double tmin, double tmax,
                                         TraceStats& stats) const override;
  bool inside(const Vec3& p) const override;
  Box3 inside_bounds() const override;
  bool blocks_light() const override { return child_->blocks_light(); }
  bool any_crossing(const Ray& ray, double tmin, double tmax, TraceStats& stats) const override;

 private:
  // The ray in the child's space with a unit direction; `stretch` is how much longer the
  // direction was there: t_child = t * stretch.
  Ray child_ray(const Ray& ray, double& stretch) const;
  void to_placed_space(Crossing& crossing, double stretch) const;

  std::shared_ptr<const Shape> child_;
  scene::Transform transform_;
  bool places_shared_;
  Box3 bounds_, inside_bounds_;
};

}  // namespace convray::geometry
