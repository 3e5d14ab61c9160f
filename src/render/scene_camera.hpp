#pragma once
// The render camera made from the scene's camera record (its frame vectors already final):
// a point of the film maps to the image plane coordinates
//   x0 = x / W - 0.5  (to the right),   y0 = 0.5 - y / H  (up),
// with film coordinates x in [0, W], y in [0, H] (y down); a pixel (i, j) is sampled at its
// centre (i + 0.5, j + 0.5) as POV-Ray 3.7 does without anti-aliasing (see camera.hpp).
//   perspective:  from location along normalize(direction + x0 right + y0 up)
//   orthographic: from location + x0 right + y0 up along normalize(direction)
//   fisheye, panoramic, spherical, cylinder: wide_projections.hpp; where a projection has no
//   ray (outside a fisheye's circle) the ray's direction is zero, and the pixel is black.
#include "core/ray.hpp"
#include "scene/scene.hpp"

namespace convray::render {

class SceneCamera {
 public:
  // Throws std::invalid_argument for an empty image or a degenerate frame (a zero direction,
  // or right and up that span no plane).
  SceneCamera(const scene::Camera& camera, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // The ray through image-plane coordinates (x0, y0) in [-0.5, 0.5]^2.
  Ray ray_through(double x0, double y0) const;
  // The ray through film point (x, y): pixel (i, j) covers [i, i + 1] x [j, j + 1].
  Ray ray_at_film(double x, double y) const;
  // The ray through pixel (i, j)'s centre.
  Ray primary_ray(int i, int j) const { return ray_at_film(i + 0.5, j + 0.5); }

 private:
  scene::Camera camera_;
  int width_, height_;
};

}  // namespace convray::render
