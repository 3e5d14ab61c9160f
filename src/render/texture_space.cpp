#include "render/texture_space.hpp"

#include "render/normal_perturbation.hpp"

namespace convray::render {

Vec3 texture_point(const geometry::Crossing& crossing, const Vec3& world_point) {
  return crossing.texture_space ? crossing.texture_space->inverse_point(world_point)
                                : world_point;
}

Vec3 perturb_normal(const scene::Normal& perturbation, const scene::Transform* texture_space,
                    const Vec3& world_point, const Vec3& normal) {
  const bool flat =
      perturbation.space.pattern == scene::Pattern::solid || perturbation.amount == 0.0;
  if (!texture_space || flat) return perturb_normal(perturbation, world_point, normal);
  // The copy's normal moved by the placement, as the parser moves it: bumps keep their length
  // when carried to the world (render/normal_perturbation.cpp), which no change of the point
  // and the normal alone reproduces under a scale that is not uniform.
  scene::Normal placed = perturbation;
  placed.space.transform = placed.space.transform.then(*texture_space);
  return perturb_normal(placed, world_point, normal);
}

}  // namespace convray::render
