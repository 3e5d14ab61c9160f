#pragma once
// Objects and probes shared by the implicit suite's tests: a torus of triangles (many
// supports along a line); the same torus with a point, a segment, an arc and POV-Ray blob
// components of other radii and strengths beside it, for the bounds that hold per primitive
// (inside_balls_test.cpp, near_hit_test.cpp); and second differences of each primitive's
// exact field, which those bounds are checked against.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "field/threshold.hpp"
#include "implicit/surface_impl.hpp"
#include "mesh/procedural.hpp"
#include "reference/random_vectors.hpp"
#include "scene/convolution_object.hpp"
#include "scene/mesh_skeleton.hpp"

namespace convray::implicit::test_objects {

// The mixed object's torus's kernel radius.
inline constexpr double kMixedRadius = 0.3;

// A torus of radii 1 and 0.35 in rings x sides quadrilaterals, as one mesh of kernel radius
// `radius`, strength 1.
inline scene::MeshComponent torus_mesh(int rings, int sides, double radius) {
  scene::MeshComponent m;
  m.triangles = scene::soup_triangles(mesh::torus(1.0, 0.35, rings, sides));
  m.weight = {1.0, radius};
  return m;
}

inline scene::ConvolutionObject mixed_object() {
  scene::ConvolutionObject object;
  object.meshes.push_back(torus_mesh(64, 32, kMixedRadius));
  object.points.push_back({Vec3(0.0, 0.0, 0.0), {0.6, 0.5}});
  object.segments.push_back({{Vec3(-0.3, 0.6, 0.0), Vec3(0.4, 0.7, 0.1)}, {1.3, 0.25}});
  field::Arc arc;
  EXPECT_TRUE(field::arc_through(Vec3(0.0, -0.6, 0.5), Vec3(0.3, -0.8, 0.6), Vec3(0.7, -0.6, 0.5), arc));
  object.arcs.push_back({arc, {0.9, 0.35}});
  object.blob_spheres.push_back({Vec3(1.0, 0.2, -0.3), {0.8, 0.4}});
  object.blob_cylinders.push_back({Vec3(-1.0, -0.2, 0.0), Vec3(-1.0, 0.4, 0.3), {0.7, 0.3}});
  object.threshold = field::threshold_for_offset(1.0, kMixedRadius, 0.5 * kMixedRadius);
  return object;
}

// At `trials` random points of the supports' box, along a random direction each, the second
// difference (step 10^-3 of the smallest radius) of the exact field of every primitive whose
// support holds the point: visit(primitive, second difference, trial). They average the
// second derivative over the step, so a bound on it holds for them.
template <class Visit>
void for_each_second_difference(const ConvolutionSurface::Impl& s, uint64_t seed, int trials,
                                Visit&& visit) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Box3 box = s.index->bounds();
  std::vector<uint32_t> ids;
  const double h = 1e-3 * s.min_radius;
  for (int trial = 0; trial < trials; ++trial) {
    const Vec3 p = box.lo + Vec3(unit(rng), unit(rng), unit(rng)) * (box.hi - box.lo);
    ids.clear();
    s.index->contain(p, ids);
    const Vec3 u = convray::testing::random_unit(rng);
    for (uint32_t id : ids) {
      visit(id, (s.value(id, p + h * u) - 2.0 * s.value(id, p) + s.value(id, p - h * u)) / (h * h),
            trial);
    }
  }
}

}  // namespace convray::implicit::test_objects
