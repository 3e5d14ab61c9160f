#pragma once
// The immutable Scene the parser produces and the renderer consumes: camera, lights,
// background, atmosphere, global settings and objects. Plain records; nothing here renders.
#include <optional>
#include <vector>

#include "scene/color.hpp"
#include "scene/object.hpp"
#include "scene/texture.hpp"
#include "util/math.hpp"

namespace convray::scene {

// The camera's frame after POV-Ray 3.7's rules (look_at, angle, sky and transforms already
// applied by the parser): a primary ray through image-plane coordinates (x0, y0) in
// [-0.5, 0.5]^2 (x0 to the right, y0 up) goes, for a perspective camera, from `location`
// along direction + x0 * right + y0 * up; for an orthographic one from
// location + x0 * right + y0 * up along `direction`.
struct Camera {
  // POV-Ray's projections (render/wide_projections.hpp for the wide ones).
  enum class Kind {
    perspective, orthographic, fisheye, panoramic, spherical, cylinder, ultra_wide_angle
  };
  Kind kind = Kind::perspective;
  int cylinder_type = 1;  // cylinder: 1 to 4
  // The wide projections' field of view in degrees: horizontal (spherical, cylinder 1 and
  // 3, ultra_wide_angle), vertical (cylinder 2 and 4) or across the image circle (fisheye);
  // `vertical_angle`
  // is spherical's second angle.
  double angle = 0.0, vertical_angle = 0.0;
  Vec3 location{0.0, 0.0, 0.0};
  Vec3 direction{0.0, 0.0, 1.0};
  Vec3 right{1.33, 0.0, 0.0};
  Vec3 up{0.0, 1.0, 0.0};
  // The point the scene said to look_at and its sky, placed by the camera's transforms: not
  // used to render (the vectors above are final), but `convray view` orbits around it.
  std::optional<Vec3> look_at = std::nullopt;
  Vec3 sky{0.0, 1.0, 0.0};
  // The lengths of right, up and direction as the items gave them, before look_at turned
  // them (a camera with look_at and no transforms; else 0): with location, look_at and sky
  // they give this camera again, bit for bit, where the final vectors' lengths may be a
  // rounding off.
  Vec3 item_lengths{0.0};
};

struct AreaLight {
  Vec3 axis1{1.0, 0.0, 0.0}, axis2{0.0, 0.0, 1.0};  // full extents of the light's rectangle
  int size1 = 1, size2 = 1;                          // lights along each axis
  int adaptive = 0;
  bool jitter = false;
  bool circular = false;
  bool orient = false;
};

struct Light {
  enum class Kind { point, spotlight, parallel };
  Kind kind = Kind::point;
  Vec3 position{0.0};
  Color color{Vec3(1.0)};
  Vec3 point_at{0.0, 0.0, 1.0};  // spotlight and parallel
  double radius = 30.0, falloff = 45.0, tightness = 0.0;  // spotlight, degrees
  bool shadowless = false;
  double fade_distance = 0.0;  // 0: no fading
  double fade_power = 0.0;
  std::optional<AreaLight> area;
};

// Gradient pigments on the infinite sphere seen by rays that leave the scene.
struct SkySphere {
  std::vector<Pigment> pigments;  // layered as POV-Ray: the last on top, earlier ones seen
                                  // through its transparent parts
  Transform transform;
};

struct Fog {
  enum class Kind { constant = 1, ground = 2 };
  Kind kind = Kind::constant;
  double distance = 0.0;
  Color color;
  double offset = 0.0, altitude = 0.0;  // ground fog
  Vec3 up{0.0, 1.0, 0.0};
  Turbulence turbulence;
};

struct GlobalSettings {
  double assumed_gamma = 1.0;  // POV-Ray 3.7 scenes say 1.0; anything else is warned about
  // POV-Ray 3.7 turns gamma correction off for older scenes (no #version, or one below 3.7)
  // that give no assumed_gamma: their colours are written as computed, not sRGB-encoded.
  bool gamma_correction = true;
  // The language version in effect when the parse ended (3.62 for a scene without #version,
  // as POV-Ray 3.7 assumes): older scenes blend transparent layers by the older rules
  // (render/layer_blend.hpp).
  double language_version = 3.7;
  int max_trace_level = 5;
  Vec3 ambient_light{1.0};
  double adc_bailout = 1.0 / 255.0;
};

struct Scene {
  Camera camera;  // POV-Ray's default camera when the scene declares none
  std::vector<Light> lights;
  Color background{Vec3(0.0)};
  std::optional<SkySphere> sky_sphere;
  std::vector<Fog> fogs;
  GlobalSettings settings;
  std::vector<ObjectPtr> objects;
};

}  // namespace convray::scene
