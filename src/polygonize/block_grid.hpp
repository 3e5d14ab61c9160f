#pragma once
// The sparse grid the polygonizer works on: a lattice of points origin + cell * (i, j, k),
// grouped into blocks of kBlockCells^3 cells, of which only the blocks that touch some
// primitive's support are visited. Every lattice point outside those blocks lies outside
// every support, where F = 0 < T, so the surface never crosses an unvisited block: that is
// what lets a sparse extraction still give a closed surface.
#include <cstdint>
#include <vector>

#include "util/math.hpp"

namespace convray::polygonize {

inline constexpr int kBlockCells = 8;

struct GridIndex {
  int64_t i = 0, j = 0, k = 0;
};

class BlockGrid {
 public:
  // A lattice of spacing `cell` covering `bounds` with a margin of at least one cell on every
  // side. Throws std::invalid_argument when it would need more than kMaxPointsPerAxis points
  // along an axis (the edge keys pack three such indices into 64 bits).
  BlockGrid(const Box3& bounds, double cell);

  static constexpr int64_t kMaxPointsPerAxis = int64_t(1) << 20;

  double cell() const { return cell_; }
  const Vec3& origin() const { return origin_; }
  // Lattice points along each axis, and blocks.
  const GridIndex& points() const { return points_; }
  const GridIndex& blocks() const { return blocks_; }

  // The position of a lattice point: always the same expression, so that blocks sharing a
  // point evaluate the field at exactly the same coordinates.
  Vec3 position(int64_t i, int64_t j, int64_t k) const {
    return origin_ + cell_ * Vec3(double(i), double(j), double(k));
  }
  uint64_t point_key(int64_t i, int64_t j, int64_t k) const {
    return uint64_t(i) | (uint64_t(j) << 20) | (uint64_t(k) << 40);
  }
  GridIndex point_from_key(uint64_t key) const {
    const uint64_t mask = (uint64_t(1) << 20) - 1;
    return {int64_t(key & mask), int64_t((key >> 20) & mask), int64_t((key >> 40) & mask)};
  }
  uint64_t block_key(const GridIndex& b) const {
    return uint64_t(b.i) +
           uint64_t(blocks_.i) * (uint64_t(b.j) + uint64_t(blocks_.j) * uint64_t(b.k));
  }
  GridIndex block_from_key(uint64_t key) const;

  // The blocks whose closed box touches one of the closed `boxes`, as sorted unique keys.
  std::vector<uint64_t> touched_blocks(const std::vector<Box3>& boxes) const;

 private:
  double cell_;
  Vec3 origin_;
  GridIndex points_, blocks_;
};

}  // namespace convray::polygonize
