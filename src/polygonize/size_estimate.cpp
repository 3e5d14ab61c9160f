#include "polygonize/size_estimate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "polygonize/block_grid.hpp"
#include "polygonize/polygonize.hpp"

namespace convray::polygonize {

namespace {

// Memory per visited block (its key, its list of pieces) and per output triangle (its share
// of the crossed edges, of the vertices with their normals and residuals, of the pieces the
// blocks hand over, and of the mesh statistics and the file written afterwards), measured as
// peak resident memory over cells from R/4 to R/64 on the example soup, rounded up.
constexpr uint64_t kBytesPerBlock = 96;
constexpr uint64_t kBytesPerTriangle = 400;
constexpr uint64_t kNoSampleBytes = uint64_t(1) << 40;

Box3 support_bounds(const FieldSource& source) {
  Box3 bounds;
  for (const Box3& box : source.supports) {
    if (!box.empty()) bounds.extend(box.lo), bounds.extend(box.hi);
  }
  return bounds;
}

double total_blocks(const BlockGrid& grid) {
  return double(grid.blocks().i) * double(grid.blocks().j) * double(grid.blocks().k);
}

// The smallest whole coarsening whose lattice has at most `limit` blocks in all.
double coarsening_for(const Box3& bounds, double cell, double limit) {
  double factor = 1.0;
  while (total_blocks(BlockGrid(bounds, cell * factor)) > limit) {
    factor *= std::max(1.25, std::cbrt(total_blocks(BlockGrid(bounds, cell * factor)) / limit));
  }
  return factor;
}

}  // namespace

SizeEstimate estimate_size(const FieldSource& source, double cell) {
  SizeEstimate estimate;
  const Box3 bounds = support_bounds(source);
  if (bounds.empty()) return estimate;
  const BlockGrid grid(bounds, cell);  // throws for a lattice too large per axis
  const double factor = coarsening_for(bounds, cell, 1e6);
  const double touched =
      double(BlockGrid(bounds, cell * factor).touched_blocks(source.supports).size());
  estimate.blocks = uint64_t(std::min(total_blocks(grid), touched * factor * factor * factor));
  estimate.bytes = estimate.blocks * kBytesPerBlock;
  // A job whose blocks alone cannot fit in any memory is not worth a sample pass.
  if (estimate.blocks < kSampledBlocks || estimate.bytes > kNoSampleBytes) return estimate;

  // The sample pass: the same extraction, a lattice with about kSampledBlocks / 20 blocks.
  const double sample_factor = std::cbrt(double(estimate.blocks) / double(kSampledBlocks / 20));
  PolygonizeOptions options;
  options.cell = cell * sample_factor;
  const auto start = std::chrono::steady_clock::now();
  PolygonizeStats stats;
  const SurfaceMesh sample = polygonize(source, options, &stats);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  estimate.triangles =
      uint64_t(double(sample.soup.triangles.size()) * sample_factor * sample_factor);
  estimate.bytes += estimate.triangles * kBytesPerTriangle;
  if (stats.blocks > 0) estimate.seconds = seconds * double(estimate.blocks) / double(stats.blocks);
  return estimate;
}

}  // namespace convray::polygonize
