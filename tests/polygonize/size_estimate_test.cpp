// The size of a polygonization before it runs (issue 17), against the extraction itself: the
// blocks are an upper estimate of those visited, the triangles within a quarter of those made;
// and the lattice's support boxes, one per distinct triangle.
#include "polygonize/size_estimate.hpp"

#include <gtest/gtest.h>

#include "analytic_fields.hpp"
#include "polygonize/polygonize.hpp"

namespace convray::polygonize {
namespace {

using testing::KernelSum;

TEST(SizeEstimate, BoundsTheBlocksAndPredictsTheTrianglesOfALargeJob) {
  const testing::ToPoint center(Vec3(0.1, -0.2, 0.3));
  KernelSum sum{{{&center, 1.0, 1.0, testing::cube(center.center, 1.0)}}};
  const FieldSource source = sum.source(0.3);
  const double cell = 0.009;  // about 23,000 blocks: sampled
  const SizeEstimate estimate = estimate_size(source, cell);
  PolygonizeStats stats;
  const SurfaceMesh m = polygonize(source, {.cell = cell}, &stats);
  ASSERT_GE(stats.blocks, kSampledBlocks);
  EXPECT_GE(estimate.blocks, stats.blocks);
  EXPECT_LE(double(estimate.blocks), 1.5 * double(stats.blocks));
  EXPECT_NEAR(double(estimate.triangles), double(m.soup.triangles.size()),
              0.25 * double(m.soup.triangles.size()));
  EXPECT_GT(estimate.seconds, 0.0);
  EXPECT_GT(estimate.bytes, estimate.triangles * 100);
}

TEST(SizeEstimate, ASmallJobIsCountedNotSampled) {
  const testing::ToPoint center(Vec3(0.0));
  KernelSum sum{{{&center, 1.0, 1.0, testing::cube(center.center, 1.0)}}};
  const FieldSource source = sum.source(0.3);
  const SizeEstimate estimate = estimate_size(source, 0.07);
  PolygonizeStats stats;
  polygonize(source, {.cell = 0.07}, &stats);
  EXPECT_EQ(estimate.blocks, stats.blocks);  // no coarsening at this size: the exact count
  EXPECT_EQ(estimate.triangles, 0u);
  EXPECT_EQ(estimate.seconds, 0.0);
}

TEST(SizeEstimate, ALatticeTooLargePerAxisIsRefusedAsPolygonizeRefusesIt) {
  const testing::ToPoint center(Vec3(0.0));
  KernelSum sum{{{&center, 1.0, 1.0, testing::cube(center.center, 1.0)}}};
  EXPECT_THROW(estimate_size(sum.source(0.3), 1e-7), std::invalid_argument);
}

}  // namespace
}  // namespace convray::polygonize
