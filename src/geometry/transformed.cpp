#include "geometry/transformed.hpp"

#include "core/box.hpp"

namespace convray::geometry {

TransformedShape::TransformedShape(std::shared_ptr<const Shape> child,
                                   const scene::Transform& transform, bool places_shared)
    : child_(std::move(child)),
      transform_(transform),
      places_shared_(places_shared),
      bounds_(transform_box(transform.forward(), child_->bounds())),
      inside_bounds_(transform_box(transform.forward(), child_->inside_bounds())) {}

Box3 TransformedShape::bounds() const { return bounds_; }
Box3 TransformedShape::inside_bounds() const { return inside_bounds_; }

Ray TransformedShape::child_ray(const Ray& ray, double& stretch) const {
  const Vec3 direction = transform_.inverse_vector(ray.direction);
  stretch = glm::length(direction);
  return Ray{transform_.inverse_point(ray.origin), direction / stretch};
}

void TransformedShape::to_placed_space(Crossing& crossing, double stretch) const {
  crossing.t /= stretch;
  crossing.normal = glm::normalize(transform_.normal(crossing.normal));
  if (places_shared_) crossing.texture_space = &transform_;
}

void TransformedShape::crossings(const Ray& ray, double tmin, double tmax,
                                 std::vector<Crossing>& out, TraceStats& stats) const {
  double stretch = 1.0;
  const Ray local = child_ray(ray, stretch);
  const size_t first = out.size();
  child_->crossings(local, tmin * stretch, tmax * stretch, out, stats);
  for (size_t i = first; i < out.size(); ++i) to_placed_space(out[i], stretch);
}

std::optional<Crossing> TransformedShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                         TraceStats& stats) const {
  double stretch = 1.0;
  const Ray local = child_ray(ray, stretch);
  auto crossing = child_->first_crossing(local, tmin * stretch, tmax * stretch, stats);
  if (crossing) to_placed_space(*crossing, stretch);
  return crossing;
}

bool TransformedShape::any_crossing(const Ray& ray, double tmin, double tmax,
                                    TraceStats& stats) const {
  double stretch = 1.0;
  const Ray local = child_ray(ray, stretch);
  return child_->any_crossing(local, tmin * stretch, tmax * stretch, stats);
}

bool TransformedShape::inside(const Vec3& p) const {
  return child_->inside(transform_.inverse_point(p));
}

}  // namespace convray::geometry
