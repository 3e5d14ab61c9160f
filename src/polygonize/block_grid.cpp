#include "polygonize/block_grid.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace convray::polygonize {

BlockGrid::BlockGrid(const Box3& bounds, double cell) : cell_(cell) {
  if (!(cell > 0.0) || !std::isfinite(cell)) throw std::invalid_argument("the cell must be > 0");
  if (bounds.empty()) throw std::invalid_argument("nothing to polygonize: the field is zero");
  // Two cells of margin: the outermost lattice points are then outside every support. The
  // origin is also shifted by irrational-looking fractions of a cell, different per axis, so
  // that flat parts of a model aligned with its bounds (a sheet, a box's faces) do not put
  // their surface exactly through lattice points, where vertices would crowd into slivers.
  origin_ = bounds.lo - cell * Vec3(2.0 + 0.3819660113, 2.0 + 0.2763932022, 2.0 + 0.1458980338);
  const Vec3 extent = bounds.hi - bounds.lo;
  int64_t* point_counts[3] = {&points_.i, &points_.j, &points_.k};
  int64_t* block_counts[3] = {&blocks_.i, &blocks_.j, &blocks_.k};
  for (int axis = 0; axis < 3; ++axis) {
    const double cells = std::ceil(extent[axis] / cell) + 5.0;
    const double blocks = std::ceil(cells / kBlockCells);
    if (!(blocks * kBlockCells + 1.0 <= double(kMaxPointsPerAxis))) {
      std::ostringstream message;
      message << "the cell " << cell << " is too small for a model " << extent[axis]
              << " across: the grid would need " << cells << " cells along "
              << "xyz"[axis] << ", the limit is " << kMaxPointsPerAxis - 1;
      throw std::invalid_argument(message.str());
    }
    *block_counts[axis] = int64_t(blocks);
    *point_counts[axis] = int64_t(blocks) * kBlockCells + 1;
  }
}

GridIndex BlockGrid::block_from_key(uint64_t key) const {
  const uint64_t nx = uint64_t(blocks_.i), ny = uint64_t(blocks_.j);
  return {int64_t(key % nx), int64_t((key / nx) % ny), int64_t(key / (nx * ny))};
}

std::vector<uint64_t> BlockGrid::touched_blocks(const std::vector<Box3>& boxes) const {
  const double block_size = cell_ * kBlockCells;
  // Block b spans [origin + b * size, origin + (b + 1) * size]; a box touching a shared face
  // touches both blocks, so the range is widened by a hair on both ends.
  const auto range = [&](double lo, double hi, int axis, int64_t& first, int64_t& last) {
    const int64_t count = axis == 0 ? blocks_.i : axis == 1 ? blocks_.j : blocks_.k;
    first = std::clamp<int64_t>(int64_t(std::floor((lo - origin_[axis]) / block_size - 1e-9)), 0,
                                count - 1);
    last = std::clamp<int64_t>(int64_t(std::floor((hi - origin_[axis]) / block_size + 1e-9)), 0,
                               count - 1);
  };
  tbb::enumerable_thread_specific<std::vector<uint64_t>> per_thread;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, boxes.size(), 1024), [&](const auto& r) {
    std::vector<uint64_t>& keys = per_thread.local();
    for (size_t n = r.begin(); n < r.end(); ++n) {
      const Box3& box = boxes[n];
      if (box.empty()) continue;
      GridIndex first, last;
      range(box.lo.x, box.hi.x, 0, first.i, last.i);
      range(box.lo.y, box.hi.y, 1, first.j, last.j);
      range(box.lo.z, box.hi.z, 2, first.k, last.k);
      for (int64_t k = first.k; k <= last.k; ++k) {
        for (int64_t j = first.j; j <= last.j; ++j) {
          for (int64_t i = first.i; i <= last.i; ++i) keys.push_back(block_key({i, j, k}));
        }
      }
      // Keep the per-thread lists from growing with the overlap between neighbours.
      if (keys.size() > (size_t(1) << 22)) {
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
      }
    }
  });
  std::vector<uint64_t> all;
  for (std::vector<uint64_t>& keys : per_thread) all.insert(all.end(), keys.begin(), keys.end());
  tbb::parallel_sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

}  // namespace convray::polygonize
