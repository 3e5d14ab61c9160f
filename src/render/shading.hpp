#pragma once
// Phong shading with one point light and hard shadows: the light is tested with a shadow ray
// through the same Traceable, so a surface shadows itself.
#include "implicit/ray.hpp"
#include "render/render_stats.hpp"
#include "render/traceable.hpp"
#include "util/math.hpp"

namespace convray::render {

// Colours are linear RGB (not sRGB-encoded): light adds up linearly; image_file encodes.
struct PointLight {
  Vec3 position{0.0};
  Vec3 color{1.0};
};

struct Material {
  Vec3 color{0.80, 0.60, 0.42};  // diffuse albedo: a warm clay
  double ambient = 0.08;         // fraction of the albedo seen without any light
  double diffuse = 0.85;         // Lambert term weight
  double specular = 0.30;        // Phong highlight weight (white, not tinted by the albedo)
  double shininess = 40.0;       // Phong exponent n of (R.V)^n
};

struct Lighting {
  PointLight light;
  Material material;
  Vec3 background{0.015, 0.018, 0.025};  // a camera ray that misses everything
  bool shadows = true;
  // Shadow rays start this far from the surface along its normal, so they do not find the
  // crossing they leave from. It should exceed the error of the hit points and stay well
  // below the thinnest feature; 0 lets render_image use 1e-9 of the scene's bounding diagonal.
  double shadow_bias = 0.0;
};

// The Phong formula at a lit or shadowed point, without any ray:
//   colour = albedo * ambient + visible * light * (albedo * diffuse * max(N.L, 0)
//                                                  + specular * max(R.V, 0)^n),
// with R = 2 (N.L) N - L the light's mirror direction, and no highlight where N.L <= 0.
// `normal`, `to_light` and `to_viewer` are unit vectors; `visible` is 0 or 1 (hard shadows).
Vec3 phong(const Material& material, const PointLight& light, const Vec3& normal,
           const Vec3& to_light, const Vec3& to_viewer, double visible);

// The colour seen along `ray` at `hit`: the normal is turned towards the viewer (a camera
// inside the solid sees the inside lit), then one shadow ray towards the light if it can
// reach the point at all. `scene_bounds` is scene.bounds(), computed once by the caller.
Vec3 shade(const Traceable& scene, const Box3& scene_bounds, const Ray& ray, const SurfaceHit& hit,
           const Lighting& lighting, RenderStats& stats);

}  // namespace convray::render
