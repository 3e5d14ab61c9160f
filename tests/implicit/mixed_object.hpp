#pragma once
// A convolution object with every kind of primitive, for the tests of bounds that hold per
// primitive (inside_balls_test.cpp, near_hit_test.cpp): a torus of triangles (many supports
// along a line), with a point, a segment, an arc and POV-Ray blob components of other radii
// and strengths beside it.
#include <gtest/gtest.h>

#include "field/threshold.hpp"
#include "mesh/procedural.hpp"
#include "scene/convolution_object.hpp"
#include "scene/mesh_skeleton.hpp"

namespace convray::implicit::test_objects {

// The torus's kernel radius.
inline constexpr double kMixedRadius = 0.3;

inline scene::ConvolutionObject mixed_object() {
  scene::ConvolutionObject object;
  const mesh::TriangleSoup soup = mesh::torus(1.0, 0.35, 64, 32);
  scene::MeshComponent m;
  m.triangles = scene::soup_triangles(soup);
  m.weight = {1.0, kMixedRadius};
  object.meshes.push_back(m);
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

}  // namespace convray::implicit::test_objects
