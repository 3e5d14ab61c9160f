#include "render/lights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/sample_hash.hpp"

namespace convray::render {

namespace {

double radians(double degrees) { return degrees * kPi / 180.0; }

// Position in [-0.5, 0.5] of light k of n along one axis, moved within its cell by `jitter`
// in [-0.5, 0.5) cells.
double grid_coordinate(int k, int n, double jitter) {
  if (n <= 1) return 0.0;
  const double cell = 1.0 / double(n - 1);
  return std::clamp(k * cell - 0.5 + jitter * cell, -0.5, 0.5);
}

// Shirley and Chiu's concentric map: the square [-0.5, 0.5]^2 onto the disc of radius 0.5,
// keeping areas proportional (an evenly spread grid stays evenly spread).
Vec2 square_to_disc(double u, double v) {
  const double a = 2.0 * u, b = 2.0 * v;  // [-1, 1]^2
  if (a == 0.0 && b == 0.0) return Vec2(0.0);
  double r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (kPi / 4.0) * (b / a);
  } else {
    r = b;
    phi = kPi / 2.0 - (kPi / 4.0) * (a / b);
  }
  return 0.5 * r * Vec2(std::cos(phi), std::sin(phi));
}

// The light's axes turned so that its plane faces `point`, lengths kept.
void orient_axes(const Vec3& position, const Vec3& point, Vec3& axis1, Vec3& axis2) {
  const Vec3 toward = point - position;
  const double distance = glm::length(toward);
  if (!(distance > 0.0)) return;
  const Vec3 w = toward / distance;
  Vec3 u = axis1 - glm::dot(axis1, w) * w;
  if (glm::length(u) < 1e-9 * glm::length(axis1)) {
    // axis1 points at the point: any perpendicular will do.
    u = std::abs(w.x) < 0.9 ? glm::cross(w, Vec3(1, 0, 0)) : glm::cross(w, Vec3(0, 1, 0));
  }
  u = glm::normalize(u);
  const Vec3 v = glm::cross(w, u);
  axis1 = glm::length(axis1) * u;
  axis2 = glm::length(axis2) * v;
}

}  // namespace

double spotlight_factor(const scene::Light& light, const Vec3& light_to_point) {
  const Vec3 axis = light.point_at - light.position;
  const double axis_length = glm::length(axis);
  if (!(axis_length > 0.0)) return 1.0;
  const double cos_angle = glm::dot(axis / axis_length, light_to_point);
  const double cos_falloff = std::cos(radians(light.falloff));
  const double cos_radius = std::cos(radians(light.radius));
  if (cos_angle < cos_falloff) return 0.0;
  const double tight = light.tightness != 0.0 ? std::pow(cos_angle, light.tightness) : 1.0;
  if (cos_angle >= cos_radius || cos_radius <= cos_falloff) return tight;
  const double t = (cos_angle - cos_falloff) / (cos_radius - cos_falloff);
  return tight * t * t * (3.0 - 2.0 * t);
}

double fade_factor(const scene::Light& light, double distance) {
  if (!(light.fade_distance > 0.0) || !(light.fade_power > 0.0)) return 1.0;
  return 2.0 / (1.0 + std::pow(distance / light.fade_distance, light.fade_power));
}

std::optional<LightArrival> light_arrival(const scene::Light& light, const Vec3& point) {
  LightArrival arrival;
  if (light.kind == scene::Light::Kind::parallel) {
    const Vec3 direction = light.position - light.point_at;
    const double length = glm::length(direction);
    if (!(length > 0.0)) return std::nullopt;
    arrival.to_light = direction / length;
    arrival.distance = std::numeric_limits<double>::infinity();
    arrival.color = light.color.rgb;
  } else {
    const Vec3 toward = light.position - point;
    arrival.distance = glm::length(toward);
    if (!(arrival.distance > 0.0)) return std::nullopt;
    arrival.to_light = toward / arrival.distance;
    arrival.color = light.color.rgb * fade_factor(light, arrival.distance);
    if (light.kind == scene::Light::Kind::spotlight) {
      arrival.color *= spotlight_factor(light, -arrival.to_light);
    }
  }
  if (arrival.color == Vec3(0.0)) return std::nullopt;
  return arrival;
}

std::vector<Vec3> area_light_points(const scene::Light& light, const Vec3& point,
                                    uint64_t jitter_seed) {
  if (!light.area) return {light.position};
  const scene::AreaLight& area = *light.area;
  Vec3 axis1 = area.axis1, axis2 = area.axis2;
  if (area.orient) orient_axes(light.position, point, axis1, axis2);
  const int n1 = std::max(area.size1, 1), n2 = std::max(area.size2, 1);

  std::vector<Vec3> points;
  points.reserve(size_t(n1) * size_t(n2));
  for (int j = 0; j < n2; ++j) {
    for (int i = 0; i < n1; ++i) {
      double ju = 0.0, jv = 0.0;
      if (area.jitter) {
        ju = unit_from_hash(hash_values(jitter_seed, uint64_t(i), uint64_t(j), 1)) - 0.5;
        jv = unit_from_hash(hash_values(jitter_seed, uint64_t(i), uint64_t(j), 2)) - 0.5;
      }
      double u = grid_coordinate(i, n1, ju), v = grid_coordinate(j, n2, jv);
      if (area.circular) {
        const Vec2 disc = square_to_disc(u, v);
        u = disc.x;
        v = disc.y;
      }
      points.push_back(light.position + u * axis1 + v * axis2);
    }
  }
  return points;
}

}  // namespace convray::render
