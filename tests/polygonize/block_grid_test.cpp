// The polygonizer's sparse lattice (block_grid.hpp): its margin around the bounds, its keys
// (round trips and no two points or blocks sharing one), its limits, and touched_blocks
// against brute force over every block, boxes exactly on block faces included.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <stdexcept>

#include "polygonize/block_grid.hpp"

namespace convray::polygonize {
namespace {

Box3 box(const Vec3& lo, const Vec3& hi) { return {lo, hi}; }

bool touches(const Box3& a, const Box3& b) {
  for (int axis = 0; axis < 3; ++axis) {
    if (a.hi[axis] < b.lo[axis] || b.hi[axis] < a.lo[axis]) return false;
  }
  return true;
}

Box3 block_box(const BlockGrid& grid, int64_t i, int64_t j, int64_t k) {
  return {grid.position(i * kBlockCells, j * kBlockCells, k * kBlockCells),
          grid.position((i + 1) * kBlockCells, (j + 1) * kBlockCells, (k + 1) * kBlockCells)};
}

TEST(BlockGrid, LatticeCoversTheBoundsWithAMargin) {
  std::mt19937_64 rng(1471);
  std::uniform_real_distribution<double> position(-100.0, 100.0), unit(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    Box3 bounds;
    bounds.extend({position(rng), position(rng), position(rng)});
    bounds.extend({position(rng), position(rng), position(rng)});
    if (i % 10 == 0) bounds.hi = bounds.lo;  // a single point
    const double cell = std::pow(10.0, -1.0 + 2.0 * unit(rng));
    const BlockGrid grid(bounds, cell);
    EXPECT_EQ(grid.cell(), cell);
    const GridIndex& n = grid.points();
    const GridIndex& b = grid.blocks();
    EXPECT_EQ(n.i, b.i * kBlockCells + 1);
    EXPECT_EQ(n.j, b.j * kBlockCells + 1);
    EXPECT_EQ(n.k, b.k * kBlockCells + 1);
    const Vec3 first = grid.position(0, 0, 0), last = grid.position(n.i - 1, n.j - 1, n.k - 1);
    EXPECT_EQ(first, grid.origin());
    for (int axis = 0; axis < 3; ++axis) {
      // At least one cell of margin on each side: the outermost points are outside the bounds.
      EXPECT_LE(first[axis], bounds.lo[axis] - cell) << i;
      EXPECT_GE(last[axis], bounds.hi[axis] + cell) << i;
      // And not absurdly more: the blocks needed plus one.
      const double needed = (bounds.hi[axis] - bounds.lo[axis]) / cell + 5.0;
      const int64_t blocks = axis == 0 ? b.i : axis == 1 ? b.j : b.k;
      EXPECT_LE(blocks, int64_t(std::ceil(needed / kBlockCells)) + 1) << i;
    }
    const Vec3 p = grid.position(3, 5, 7);
    EXPECT_NEAR(p.x, grid.origin().x + 3.0 * cell, 1e-12 * (1.0 + std::abs(p.x)));
    EXPECT_NEAR(p.y, grid.origin().y + 5.0 * cell, 1e-12 * (1.0 + std::abs(p.y)));
    EXPECT_NEAR(p.z, grid.origin().z + 7.0 * cell, 1e-12 * (1.0 + std::abs(p.z)));
  }
}

TEST(BlockGrid, RejectsBadCellsEmptyBoundsAndTooFineLattices) {
  const Box3 unit_box = box(Vec3(0.0), Vec3(1.0));
  for (double cell : {0.0, -1.0, double(NAN), double(INFINITY)}) {
    EXPECT_THROW((BlockGrid{unit_box, cell}), std::invalid_argument) << cell;
  }
  EXPECT_THROW((BlockGrid{Box3{}, 0.1}), std::invalid_argument);
  // 2^20 points per axis at most: a model 1 across with cells of 1e-6 needs 10^6 + 5 cells,
  // 2e-7 needs 5 * 10^6.
  EXPECT_NO_THROW((BlockGrid{unit_box, 1e-6}));
  try {
    const BlockGrid too_fine(unit_box, 2e-7);
    FAIL() << "a lattice of 5e6 points per axis was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("too small"), std::string::npos) << e.what();
  }
}

// Keys: every lattice point and every block of a grid gets its own, and reads back.
TEST(BlockGrid, KeysAreDistinctAndReadBack) {
  const BlockGrid grid(box(Vec3(0.0), Vec3(30.0, 20.0, 10.0)), 1.0);
  const GridIndex& b = grid.blocks();
  std::set<uint64_t> block_keys;
  for (int64_t k = 0; k < b.k; ++k) {
    for (int64_t j = 0; j < b.j; ++j) {
      for (int64_t i = 0; i < b.i; ++i) {
        const uint64_t key = grid.block_key({i, j, k});
        EXPECT_LT(key, uint64_t(b.i * b.j * b.k));
        EXPECT_TRUE(block_keys.insert(key).second);
        const GridIndex back = grid.block_from_key(key);
        EXPECT_EQ(back.i, i);
        EXPECT_EQ(back.j, j);
        EXPECT_EQ(back.k, k);
      }
    }
  }
  const GridIndex& n = grid.points();
  std::set<uint64_t> point_keys;
  for (int64_t k = 0; k < n.k; ++k) {
    for (int64_t j = 0; j < n.j; ++j) {
      for (int64_t i = 0; i < n.i; ++i) {
        const uint64_t key = grid.point_key(i, j, k);
        EXPECT_TRUE(point_keys.insert(key).second);
        const GridIndex back = grid.point_from_key(key);
        ASSERT_TRUE(back.i == i && back.j == j && back.k == k) << i << " " << j << " " << k;
      }
    }
  }
  // Indices up to the limit, 2^20 - 1, read back too (three of them fill 60 bits).
  std::mt19937_64 rng(1472);
  std::uniform_int_distribution<int64_t> index(0, BlockGrid::kMaxPointsPerAxis - 1);
  for (int t = 0; t < 10000; ++t) {
    const int64_t i = t == 0 ? BlockGrid::kMaxPointsPerAxis - 1 : index(rng), j = index(rng),
                  k = index(rng);
    const GridIndex back = grid.point_from_key(grid.point_key(i, j, k));
    ASSERT_TRUE(back.i == i && back.j == j && back.k == k) << i << " " << j << " " << k;
    EXPECT_LT(grid.point_key(i, j, k), uint64_t(1) << 60);
  }
}

// touched_blocks: every block whose closed box touches a closed box is there, and nothing
// farther than a hair (the documented widening on shared faces) from one.
TEST(BlockGrid, TouchedBlocksAreTheBlocksTheBoxesReach) {
  std::mt19937_64 rng(1473);
  std::uniform_real_distribution<double> position(0.0, 60.0), size(0.0, 6.0), unit(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const BlockGrid grid(box(Vec3(0.0), Vec3(60.0)), 0.5 + unit(rng));
    const GridIndex& nb = grid.blocks();
    std::vector<Box3> boxes;
    const int count = 1 + int(30 * unit(rng));
    for (int i = 0; i < count; ++i) {
      Vec3 lo(position(rng), position(rng), position(rng));
      Vec3 hi = lo + Vec3(size(rng), size(rng), size(rng));
      if (i % 3 == 0) {  // exactly on a block face: the same expression as the grid's
        const int axis = i % 2;
        const int64_t b = int64_t(unit(rng) * nb.i);
        const double face = block_box(grid, b, b, b).lo[axis];
        (i % 4 == 0 ? hi : lo)[axis] = face;
        if (lo[axis] > hi[axis]) std::swap(lo[axis], hi[axis]);
      }
      boxes.push_back(box(lo, hi));
    }
    boxes.push_back(Box3{});  // an empty box touches nothing
    const std::vector<uint64_t> got = grid.touched_blocks(boxes);
    ASSERT_TRUE(std::is_sorted(got.begin(), got.end()));
    ASSERT_TRUE(std::adjacent_find(got.begin(), got.end()) == got.end());
    const double hair = 1e-7 * grid.cell() * kBlockCells;
    for (int64_t k = 0; k < nb.k; ++k) {
      for (int64_t j = 0; j < nb.j; ++j) {
        for (int64_t i = 0; i < nb.i; ++i) {
          const Box3 block = block_box(grid, i, j, k);
          const Box3 grown{block.lo - Vec3(hair), block.hi + Vec3(hair)};
          bool touched = false, near = false;
          for (const Box3& b : boxes) {
            if (b.empty()) continue;
            touched = touched || touches(block, b);
            near = near || touches(grown, b);
          }
          const bool listed = std::binary_search(got.begin(), got.end(), grid.block_key({i, j, k}));
          if (touched) EXPECT_TRUE(listed) << trial << ": block " << i << " " << j << " " << k;
          if (listed) EXPECT_TRUE(near) << trial << ": block " << i << " " << j << " " << k;
        }
      }
    }
  }
}

}  // namespace
}  // namespace convray::polygonize
