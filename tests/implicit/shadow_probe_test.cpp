// Shadow rays (RootMode::any) that enter a cluster of supports from outside take one sample
// in its middle before any window (window_march.cpp): against the reference tracer's roots,
// for rays from outside the supports towards random points of a torus's box, ending
// anywhere (before the object, inside a cluster, beyond it), so that some are blocked by
// that sample, some by the march after it, and some are lit.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "implicit/convolution_surface.hpp"
#include "implicit/reference_tracer.hpp"
#include "implicit/surface_impl.hpp"
#include "reference/random_vectors.hpp"
#include "test_objects.hpp"

namespace convray::implicit {
namespace {

TEST(ShadowProbe, RaysEnteringClustersAnswerAsTheReference) {
  scene::ConvolutionObject object;
  const double radius = 0.3;
  object.meshes.push_back(test_objects::torus_mesh(24, 12, radius));
  object.threshold = field::threshold_for_offset(1.0, radius, 0.5 * radius);
  const ConvolutionSurface surface(object, nullptr, Tracer::fast);
  const Box3 box = surface.impl().index->bounds();
  const Vec3 centre = 0.5 * (box.lo + box.hi);
  const double reach = glm::length(box.hi - box.lo);
  std::mt19937_64 rng(61);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int blocked = 0, lit = 0, disagreements = 0;
  TraceStats stats;
  for (int k = 0; k < 400; ++k) {
    const Vec3 origin = centre + reach * testing::random_unit(rng);
    const Vec3 target(box.lo.x + unit(rng) * (box.hi.x - box.lo.x),
                      box.lo.y + unit(rng) * (box.hi.y - box.lo.y),
                      box.lo.z + unit(rng) * (box.hi.z - box.lo.z));
    const Ray ray{origin, glm::normalize(target - origin)};
    const double tmax = 2.0 * reach * unit(rng);
    std::vector<double> roots;
    reference_roots(surface, ray, 0.0, tmax, roots, stats);
    const bool expected = !roots.empty();
    const bool got = surface.occluded(ray, 0.0, tmax, stats);
    disagreements += got != expected;
    (expected ? blocked : lit) += 1;
  }
  EXPECT_EQ(disagreements, 0);
  EXPECT_GT(blocked, 40);
  EXPECT_GT(lit, 40);
}

}  // namespace
}  // namespace convray::implicit
