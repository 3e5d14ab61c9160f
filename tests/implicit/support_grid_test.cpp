// The uniform grid over support boxes (support_grid.hpp) against brute force over every box:
// its candidates at a point hold every box that holds the point (closed boxes), nothing is
// returned outside the union of the boxes, the grid stays within its cell budget on thin and
// flat sets, and it stays selective (a grid that returned everything would be correct too).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "implicit/support_grid.hpp"

namespace convray::implicit {
namespace {

bool inside(const Box3& b, const Vec3& p) {
  for (int axis = 0; axis < 3; ++axis) {
    if (p[axis] < b.lo[axis] || p[axis] > b.hi[axis]) return false;
  }
  return true;
}

Box3 cube(const Vec3& center, double half) { return {center - Vec3(half), center + Vec3(half)}; }

// Points anywhere in a slightly larger region, inside boxes, and on their faces and corners.
Vec3 random_point(std::mt19937_64& rng, const std::vector<Box3>& boxes, const Box3& region) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 3), axis(0, 2);
  const int k = kind(rng);
  const Vec3 grow = 0.1 * region.extent();
  if (k == 0) {
    return region.lo - grow +
           (region.extent() + 2.0 * grow) * Vec3(unit(rng), unit(rng), unit(rng));
  }
  const Box3& b = boxes[std::uniform_int_distribution<size_t>(0, boxes.size() - 1)(rng)];
  Vec3 p = b.lo + (b.hi - b.lo) * Vec3(unit(rng), unit(rng), unit(rng));
  if (k == 2) {
    const int a = axis(rng);
    p[a] = unit(rng) < 0.5 ? b.lo[a] : b.hi[a];
  } else if (k == 3) {
    for (int a = 0; a < 3; ++a) p[a] = unit(rng) < 0.5 ? b.lo[a] : b.hi[a];
  }
  return p;
}

// Every box holding p is among the candidates, and candidates are valid, distinct indices.
// Returns how many candidates and how many true holders there were.
std::pair<size_t, size_t> check_point(const SupportGrid& grid, const std::vector<Box3>& boxes,
                                      const Vec3& p) {
  const std::span<const uint32_t> got = grid.candidates(p);
  std::vector<uint32_t> sorted(got.begin(), got.end());
  std::sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
  size_t holders = 0;
  for (uint32_t b = 0; b < boxes.size(); ++b) {
    if (!inside(boxes[b], p)) continue;
    ++holders;
    EXPECT_TRUE(std::binary_search(sorted.begin(), sorted.end(), b))
        << "box " << b << " holds (" << p.x << ", " << p.y << ", " << p.z << ")";
  }
  for (uint32_t c : sorted) EXPECT_LT(c, boxes.size());
  return {got.size(), holders};
}

Box3 union_of(const std::vector<Box3>& boxes) {
  Box3 u;
  for (const Box3& b : boxes) {
    u.extend(b.lo);
    u.extend(b.hi);
  }
  return u;
}

// Supports of primitives scattered in a cube: boxes of one radius around random points.
TEST(SupportGrid, CandidatesHoldEveryBoxContainingThePoint) {
  std::mt19937_64 rng(1451);
  std::uniform_real_distribution<double> position(-10.0, 10.0), radius(0.05, 1.5);
  for (int count : {1, 2, 7, 100, 3000}) {
    std::vector<Box3> boxes;
    for (int i = 0; i < count; ++i) {
      boxes.push_back(cube({position(rng), position(rng), position(rng)}, radius(rng)));
    }
    for (double min_cell : {0.0, 0.5, 50.0}) {
      const SupportGrid grid(boxes, min_cell);
      const Box3 region = union_of(boxes);
      size_t candidates = 0, holders = 0;
      for (int i = 0; i < 2000; ++i) {
        const auto [c, h] = check_point(grid, boxes, random_point(rng, boxes, region));
        candidates += c;
        holders += h;
      }
      EXPECT_GE(grid.entry_count(), boxes.size());
      // Selective once there are many boxes and the cells may be small: a few candidates per
      // box that really holds the point (one cell for everything would give them all).
      if (count >= 100 && min_cell < 1.0) {
        const double mean_candidates = candidates / 2000.0, mean_holders = holders / 2000.0;
        EXPECT_LT(mean_candidates, 10.0 + 20.0 * mean_holders) << count << " boxes";
        EXPECT_LT(mean_candidates, 0.2 * count) << count << " boxes";
      }
    }
  }
}

// Outside the union of the boxes: nothing, also for a point not a number.
TEST(SupportGrid, NothingOutsideTheUnionOfTheBoxes) {
  const std::vector<Box3> boxes{cube({0, 0, 0}, 1.0), cube({3, 0, 0}, 0.5)};
  const SupportGrid grid(boxes, 0.0);
  for (const Vec3& p : {Vec3(-1.0 - 1e-12, 0, 0), Vec3(3.5 + 1e-12, 0, 0), Vec3(0, 1.5, 0),
                        Vec3(0, 0, -2), Vec3(NAN, 0, 0), Vec3(0, INFINITY, 0)}) {
    EXPECT_TRUE(grid.candidates(p).empty()) << p.x << " " << p.y << " " << p.z;
  }
  // On the union's faces: the box there is among the candidates.
  EXPECT_EQ(check_point(grid, boxes, {-1.0, 0.0, 0.0}).second, 1u);
  EXPECT_EQ(check_point(grid, boxes, {3.5, 0.5, 0.5}).second, 1u);
  const SupportGrid empty(std::vector<Box3>{}, 1.0);
  EXPECT_TRUE(empty.candidates(Vec3(0.0)).empty());
  EXPECT_EQ(empty.cell_count(), 0u);
}

// A long thin row and a flat sheet of supports: the cell count stays within the grid's budget
// (2^22 cells) however flat the set, and the answers stay complete.
TEST(SupportGrid, ThinAndFlatSetsStayWithinTheCellBudget) {
  std::mt19937_64 rng(1452);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::vector<Vec3> shapes{{1e5, 1e-3, 1e-3}, {1e3, 1e3, 0.0}, {1e4, 1.0, 1e-6}};
  for (const Vec3& shape : shapes) {
    std::vector<Box3> boxes;
    for (int i = 0; i < 20000; ++i) {
      const Vec3 center = shape * Vec3(unit(rng), unit(rng), unit(rng));
      boxes.push_back(cube(center, 1e-4 + 0.5 * unit(rng)));
    }
    const SupportGrid grid(boxes, 0.0);
    EXPECT_LE(grid.cell_count(), size_t(1) << 22);
    EXPECT_GE(grid.cell_count(), 1u);
    const Box3 region = union_of(boxes);
    for (int i = 0; i < 300; ++i) check_point(grid, boxes, random_point(rng, boxes, region));
  }
}

// Boxes that share faces exactly, on a lattice of the same spacing as (or finer than) the
// cells: a point on a shared face or corner gets every box that touches it.
TEST(SupportGrid, SharedFacesAndCornersAreHeldByEveryBoxTouchingThem) {
  std::vector<Box3> boxes;
  for (int x = 0; x < 6; ++x) {
    for (int y = 0; y < 6; ++y) {
      for (int z = 0; z < 6; ++z) boxes.push_back({Vec3(x, y, z), Vec3(x + 1, y + 1, z + 1)});
    }
  }
  for (double min_cell : {0.0, 1.0, 0.37}) {
    const SupportGrid grid(boxes, min_cell);
    for (int x = 0; x <= 6; ++x) {
      for (int y = 0; y <= 6; ++y) {
        for (int z = 0; z <= 6; ++z) {
          const auto [candidates, holders] = check_point(grid, boxes, Vec3(x, y, z));
          EXPECT_GE(candidates, holders);
          check_point(grid, boxes, Vec3(x + 0.5, y, z));
          check_point(grid, boxes, Vec3(x, y + 0.5, z + 0.5));
        }
      }
    }
  }
}

}  // namespace
}  // namespace convray::implicit
