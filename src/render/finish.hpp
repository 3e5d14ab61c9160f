#pragma once
// POV-Ray 3.7's lighting model: what a finish makes of the light arriving at a point.
// Every formula below was checked against POV-Ray 3.7.0 renders of a plane seen by an
// orthographic camera (16-bit output with File_Gamma 1.0, so pixels are linear values);
// agreement to 1e-5 (the 16-bit quantum) at every probed pixel:
//
//   ambient    finish.ambient * global ambient_light * pigment
//   diffuse    finish.diffuse * (N.L)^brilliance * light * pigment        (N.L > 0 only)
//   phong      finish.phong * (R.L)^phong_size * light, R the view ray mirrored about N
//   specular   finish.specular * (N.H)^(1/roughness) * light, H = normalize(L + V)
//   metallic   highlights tinted: light * (1 + metallic (1 - F) (pigment - 1)), where
//              F = clamp(0.014567225 / (x - 1.12)^2 - 0.011612903, 0, 1) and x the angle
//              between N and L over pi/2 (POV-Ray's empirical Fresnel curve; the angle is the
//              light's: measured F = 0.0793 where F(N.L) = 0.0793 and F(N.V) = 0.390)
//   transparency  (1 - filter - transmit) scales ambient and diffuse only (not clamped:
//              filter 0.7 transmit 0.6 gives -0.3); highlights and reflection are not scaled
//   reflection constant colour times the reflected ray's colour, added
//
// Vectors are unit length; `normal` faces the viewer (the renderer flips it first).
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::render {

// ambient * ambient_light * pigment.
Vec3 ambient_term(const scene::Finish& finish, const Vec3& ambient_light, const Vec3& pigment);

// diffuse * (N.L)^brilliance; 0 where N.L <= 0.
double diffuse_factor(const scene::Finish& finish, double n_dot_l);

// phong * (R.L)^phong_size with R = D - 2 (D.N) N the mirrored view direction D; 0 where
// R.L <= 0 or phong is 0.
double phong_factor(const scene::Finish& finish, const Vec3& mirrored_view, const Vec3& to_light);

// specular * (N.H)^(1/roughness), H the half vector of L and V = -D; 0 where N.H <= 0.
double specular_factor(const scene::Finish& finish, const Vec3& normal, const Vec3& to_light,
                       const Vec3& to_viewer);

// POV-Ray's empirical Fresnel term for metallic highlights, from the cosine of incidence.
double metallic_fresnel(double cos_incidence);

// The colour highlights take: the light's, tinted towards the pigment by `metallic`.
Vec3 highlight_color(const scene::Finish& finish, const Vec3& light, const Vec3& pigment,
                     double n_dot_l);

// What one light adds at a point, split as POV-Ray weighs the parts: `diffuse` is scaled by
// the surface's opacity (1 - filter - transmit), `highlight` is not.
struct LightContribution {
  Vec3 diffuse{0.0};
  Vec3 highlight{0.0};
};

// `light` is the colour arriving (after spotlight cone, fading and shadows); `view` the
// direction of the ray that hit the point; `to_light` points at the light.
LightContribution light_contribution(const scene::Finish& finish, const Vec3& pigment,
                                     const Vec3& normal, const Vec3& view, const Vec3& to_light,
                                     const Vec3& light);

}  // namespace convray::render
