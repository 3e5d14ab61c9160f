#include "geometry/instance.hpp"

#include "core/box.hpp"
#include "scene/moved_textures.hpp"

namespace convray::geometry {

// Like TransformedShape, but the shape is shared by every placement, and crossings name the
// placement, since the shared members' textures are in the union's own space.
InstanceShape::InstanceShape(std::shared_ptr<const Shape> shared,
                             const scene::Transform& placement)
    : shared_(std::move(shared)),
      placement_(placement),
      bounds_(transform_box(placement.forward(), shared_->bounds())),
      inside_bounds_(transform_box(placement.forward(), shared_->inside_bounds())) {}

Ray InstanceShape::shared_ray(const Ray& ray, double& stretch) const {
  const Vec3 direction = placement_.inverse_vector(ray.direction);
  stretch = glm::length(direction);
  return Ray{placement_.inverse_point(ray.origin), direction / stretch};
}

void InstanceShape::to_placed_space(Crossing& crossing, double stretch) const {
  crossing.t /= stretch;
  crossing.normal = glm::normalize(placement_.normal(crossing.normal));
  crossing.texture_space = &placement_;
}

void InstanceShape::crossings(const Ray& ray, double tmin, double tmax,
                              std::vector<Crossing>& out, TraceStats& stats) const {
  double stretch = 1.0;
  const Ray local = shared_ray(ray, stretch);
  const size_t first = out.size();
  shared_->crossings(local, tmin * stretch, tmax * stretch, out, stats);
  for (size_t i = first; i < out.size(); ++i) to_placed_space(out[i], stretch);
}

std::optional<Crossing> InstanceShape::first_crossing(const Ray& ray, double tmin, double tmax,
                                                      TraceStats& stats) const {
  double stretch = 1.0;
  const Ray local = shared_ray(ray, stretch);
  auto crossing = shared_->first_crossing(local, tmin * stretch, tmax * stretch, stats);
  if (crossing) to_placed_space(*crossing, stretch);
  return crossing;
}

bool InstanceShape::any_crossing(const Ray& ray, double tmin, double tmax,
                                 TraceStats& stats) const {
  double stretch = 1.0;
  const Ray local = shared_ray(ray, stretch);
  return shared_->any_crossing(local, tmin * stretch, tmax * stretch, stats);
}

bool InstanceShape::inside(const Vec3& p) const {
  return shared_->inside(placement_.inverse_point(p));
}

namespace {

bool same_texture(const scene::TexturePtr& a, const scene::TexturePtr& b) {
  if (a == b) return true;
  return a && b && scene::same_everywhere(*a, *b);
}

}  // namespace

bool InheritedState::operator==(const InheritedState& other) const {
  return same_texture(texture, other.texture) &&
         same_texture(interior_texture, other.interior_texture) && interior == other.interior &&
         flags == other.flags;
}

const SharedUnion* SharedUnions::find(const scene::ObjectPtr& declared,
                                      const InheritedState& inherited) const {
  const auto found = built_.find(declared.get());
  if (found == built_.end()) return nullptr;
  for (const Entry& entry : found->second) {
    if (entry.inherited == inherited) return &entry.shared;
  }
  return nullptr;
}

std::shared_ptr<const Shape> SharedUnions::add(const scene::ObjectPtr& declared,
                                               const InheritedState& inherited,
                                               SharedUnion shared) {
  ++unions_;
  members_ += shared.members;
  std::shared_ptr<const Shape> shape = shared.shape;
  built_[declared.get()].push_back(Entry{declared, inherited, std::move(shared)});
  return shape;
}

}  // namespace convray::geometry
