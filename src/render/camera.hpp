#pragma once
// POV-Ray's perspective camera, reproduced exactly so that our pictures can be compared with
// POV-Ray's pixel for pixel: left-handed coordinates taken as given (x right, y up, z into
// the screen; no axis is flipped), sky <0,1,0>, `right` of length width/height along x, `up`
// of length 1, and `angle` the horizontal field of view.
#include "implicit/ray.hpp"
#include "util/math.hpp"

namespace convray::render {

using implicit::Ray;

// What a scene (or `convray quick`) says about the camera.
struct CameraSpec {
  Vec3 location{0.0, 0.0, -10.0};
  Vec3 look_at{0.0};
  double angle_degrees = 40.0;  // horizontal field of view, 0 < angle < 180
  int width = 800, height = 600;
};

class Camera {
 public:
  // Throws std::invalid_argument when the frame is degenerate: location == look_at, a view
  // straight along the sky vector, an angle outside (0, 180), or an empty image.
  explicit Camera(const CameraSpec& spec);

  int width() const { return width_; }
  int height() const { return height_; }
  const Vec3& location() const { return location_; }
  const Vec3& direction() const { return direction_; }  // towards look_at, length from angle
  const Vec3& right() const { return right_; }          // length width/height
  const Vec3& up() const { return up_; }                // length 1

  // The ray through the point (x0, y0) of the image plane, both in [-0.5, 0.5]: x0 grows to
  // the right, y0 upwards; (0, 0) is the centre of the image.
  Ray ray_through(double x0, double y0) const;

  // The primary ray of pixel (i, j), column i from the left, row j from the top. Through the
  // pixel's centre, as POV-Ray 3.7 samples without anti-aliasing: x0 = (i + 0.5)/W - 0.5,
  // y0 = 0.5 - (j + 0.5)/H. Found by rendering an off-centre sphere seen through a look_at
  // camera with `povray +W160 +H120 -A` (and at 161x97): centres reproduce all of POV-Ray's
  // silhouette pixels (0 differ), while corner samples (i/W, j/H) or POV-Ray 3.6's
  // ((H-1) - j)/H rows differ on 45-66 of ~1,600.
  Ray primary_ray(int i, int j) const;

 private:
  Vec3 location_, direction_, right_, up_;
  int width_, height_;
};

// A camera that shows all of `bounds` (assumed non-empty): it looks at the box's centre from
// the -z side and somewhat above (about 20 degrees), far enough that the box's bounding sphere
// fits in both the horizontal and the vertical field of view with a 5% margin.
CameraSpec frame_bounds(const Box3& bounds, int width, int height, double angle_degrees);

// A light above, to the left of and behind the camera, a few bounding radii away from the
// box's centre, so that shadows fall visibly down and to the right of the object.
Vec3 default_light_position(const Camera& camera, const Box3& bounds);

}  // namespace convray::render
