#pragma once
// What the geometry tests share: scene records written in a line, random rays, and the
// brute-force references (where inside() changes along a ray, found by dense sampling and
// bisection) that the shapes' crossings are compared with.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "geometry/shape.hpp"
#include "geometry/world.hpp"
#include "scene/object.hpp"

namespace convray::geometry::testing {

inline std::shared_ptr<scene::Object> make_object(scene::Shape shape,
                                                  scene::Transform transform = {}) {
  auto object = std::make_shared<scene::Object>();
  object->shape = std::move(shape);
  object->transform = transform;
  object->loc = SourceLoc{"test.pov", 7, 3};
  return object;
}

inline ShapePtr build(scene::Shape shape, scene::Transform transform = {}) {
  return build_shape(*make_object(std::move(shape), transform));
}

inline scene::TexturePtr make_texture(double red) {
  auto texture = std::make_shared<scene::Texture>();
  texture->pigment.color = scene::Color{Vec3(red, 0.0, 0.0)};
  return texture;
}

inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

// A ray from a random point at `distance` from `center`, aimed at a random point within
// `aim_radius` of it.
inline Ray random_ray(std::mt19937_64& rng, const Vec3& center, double distance,
                      double aim_radius) {
  const Vec3 origin = center + distance * random_unit(rng);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec3 aim = center + aim_radius * std::cbrt(u(rng)) * random_unit(rng);
  return Ray{origin, glm::normalize(aim - origin)};
}

// Every crossing of the whole ray (t >= 0).
inline std::vector<Crossing> crossings_of(const Shape& shape, const Ray& ray) {
  std::vector<Crossing> out;
  TraceStats stats;
  shape.crossings(ray, 0.0, INFINITY, out, stats);
  return out;
}

inline std::vector<double> crossing_distances(const Shape& shape, const Ray& ray, double tmin,
                                              double tmax) {
  std::vector<Crossing> crossings;
  TraceStats stats;
  shape.crossings(ray, tmin, tmax, crossings, stats);
  std::vector<double> t;
  for (const Crossing& c : crossings) t.push_back(c.t);
  return t;
}

// Where `inside` changes along the ray in (t0, t1): `samples` even steps, each change
// bisected to the last bit. Changes closer than a step may be missed: `min_gap` reports the
// smallest distance between two found changes, so that callers can tell a clean case.
template <class Inside>
std::vector<double> inside_changes(const Inside& inside, const Ray& ray, double t0, double t1,
                                   int samples) {
  std::vector<double> changes;
  const double step = (t1 - t0) / samples;
  bool previous = inside(ray.at(t0));
  for (int i = 1; i <= samples; ++i) {
    const double t = t0 + i * step;
    const bool now = inside(ray.at(t));
    if (now != previous) {
      double a = t - step, b = t;
      for (int k = 0; k < 200 && b - a > 0.0; ++k) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        (inside(ray.at(m)) == previous ? a : b) = m;
      }
      changes.push_back(0.5 * (a + b));
    }
    previous = now;
  }
  return changes;
}

inline double min_gap(const std::vector<double>& t) {
  double gap = INFINITY;
  for (size_t i = 1; i < t.size(); ++i) gap = std::min(gap, t[i] - t[i - 1]);
  return gap;
}

// Checks a solid's crossings on the ray against where its inside() changes: the same
// distances (to `tolerance`), ascending, normals facing out of the solid (against the ray
// where it enters). Returns false (and checks nothing) when the sampling cannot resolve the
// case (two changes within a few steps).
inline bool check_crossings_against_inside(const Shape& shape, const Ray& ray, double t0, double t1,
                                           double tolerance, int samples = 20000) {
  const double step = (t1 - t0) / samples;
  const auto changes =
      inside_changes([&](const Vec3& p) { return shape.inside(p); }, ray, t0, t1, samples);
  std::vector<Crossing> crossings;
  TraceStats stats;
  shape.crossings(ray, t0, t1, crossings, stats);
  std::vector<double> t;
  for (const Crossing& c : crossings) t.push_back(c.t);
  if (min_gap(t) < 4.0 * step || min_gap(changes) < 4.0 * step) return false;
  // Crossings within a few steps of the ends may be missed or invented by the sampling.
  auto near_end = [&](double x) { return x - t0 < 4.0 * step || t1 - x < 4.0 * step; };
  for (double x : t) {
    if (near_end(x)) return false;
  }
  EXPECT_EQ(t.size(), changes.size());
  if (t.size() != changes.size()) return true;
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(t[i], changes[i], tolerance) << i;
    if (i > 0) {
      EXPECT_LE(t[i - 1], t[i]);
    }
    // Entering (outside before): the normal faces against the ray.
    const bool entering = !shape.inside(ray.at(t[i] - 2.0 * step));
    const double facing = glm::dot(crossings[i].normal, ray.direction);
    EXPECT_NEAR(glm::length(crossings[i].normal), 1.0, 1e-12);
    if (entering) {
      EXPECT_LT(facing, 0.0) << "crossing " << i << " enters";
    } else {
      EXPECT_GT(facing, 0.0) << "crossing " << i << " leaves";
    }
  }
  return true;
}

}  // namespace convray::geometry::testing
